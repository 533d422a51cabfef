// Mixed manifolds contain the poses built by hand to satisfy their constraints (completeness), on
// top of the sampling checks of the scenario and example tests (soundness).
#include <gtest/gtest.h>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

Problem load(const char* file) {
  ParseResult r = parseSpecFile(std::string(RELPOS_DATA_DIR) + file, builtinRegistry());
  EXPECT_TRUE(r.problem);
  return *r.problem;
}

TEST(RadialGrasp, ContainsEveryGraspBuiltByHand) {
  const Problem p = load("/scenarios/scenario-d-soda-can-grasp.json");
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  Rng rng(77);
  for (int k = 0; k < 200; ++k) {
    const double psi = rng.uniform(-kPi, kPi), r = rng.uniform(0.02, 0.05);
    const double h = rng.uniform(0.05, 0.10), spin = rng.uniform(-kPi, kPi);
    const Vector3d radial(std::cos(psi), std::sin(psi), 0.0);
    const Vector3d tip = Vector3d(0.4, 0.1, 0.0) + r * radial + Vector3d(0, 0, h);
    const Vector3d z = (k % 2 ? 1.0 : -1.0) * radial;  // approach away from / towards the axis
    Isometry3d X = Isometry3d::Identity();
    X.linear() = Eigen::AngleAxisd(spin, z) * rotationBetween(Vector3d::UnitZ(), z);
    X.translation() = tip - X.linear() * Vector3d(0, 0, 0.12);
    ASSERT_LT(worstViolation(p, X), 1e-12);
    EXPECT_TRUE(someBranchContains(s, X)) << poseText(X) << "\n" << describeBranches(s);
  }
}

TEST(LineDistance, ContainsEveryLineBuiltByHand) {
  // Random problems around a known pose are in the random single-constraint tests; here the
  // special positions: the mobile line parallel to the fixed one, and (v = 0) crossing it.
  Problem p;
  p.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("l", Feature::makeLine({0, 0, 0}, {1, 0, 0}));
  p.addConstraint("distance", "K", "l", 0.5);
  p.constraints[0].parallel = false;
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  Isometry3d parallel = Isometry3d::Identity();  // l along z, 0.5 away
  parallel.linear() = rotationBetween(Vector3d::UnitX(), Vector3d::UnitZ());
  parallel.translation() = Vector3d(0, 0.5, 2.0);
  ASSERT_LT(worstViolation(p, parallel), 1e-12);
  EXPECT_TRUE(someBranchContains(s, parallel)) << describeBranches(s);
  p.constraints[0].value = p.constraints[0].min = p.constraints[0].max = 0.0;
  const Solution crossing = solve(p, builtinRegistry());
  Isometry3d through = Isometry3d::Identity();  // l crossing K at z = 1, tilted
  through.linear() = Eigen::AngleAxisd(0.7, Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  through.translation() = Vector3d(0, 0, 1) - through.linear() * Vector3d(0.3, 0, 0);
  ASSERT_LT(worstViolation(p, through), 1e-12);
  EXPECT_TRUE(someBranchContains(crossing, through)) << describeBranches(crossing);
}

}  // namespace
}  // namespace relpos::test
