// The PMF worked example (paper 003 §VI-A, 000 §VI-A): one branch, one rotational DOF, no
// translational DOF, and at φ = 0 the pose of eq. (17).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

Problem workedExample() {
  ParseResult r =
      parseSpecFile(RELPOS_DATA_DIR "/examples/pmf-simple-example.json", builtinRegistry());
  EXPECT_TRUE(r.errors.empty());
  return *r.problem;
}

TEST(WorkedExample, OneBranchOneRotationalDof) {
  Problem p = workedExample();
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  ASSERT_EQ(s.branches.size(), 1u);
  EXPECT_EQ(s.branches[0].manifold->dof(), 1);
  EXPECT_EQ(s.branches[0].manifold->rotationalDof(), 1);
  EXPECT_EQ(s.branches[0].manifold->translationalDof(), 0);
  EXPECT_TRUE(s.conflicts.empty());
}

TEST(WorkedExample, PoseAtZeroIsEquation17) {
  Problem p = workedExample();
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved);
  Eigen::Matrix4d eq17;
  eq17 << 0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  Isometry3d X = s.branches[0].manifold->pose(Params{});
  EXPECT_LT((X.matrix() - eq17).cwiseAbs().maxCoeff(), 1e-12) << X.matrix();
}

TEST(WorkedExample, EveryPoseOnTheBranchSatisfiesTheInput) {
  Problem p = workedExample();
  Solution s = solve(p, builtinRegistry());
  std::string where;
  EXPECT_LT(worstSampledViolation(p, s, 500, 1, &where), 1e-9) << where;
}

TEST(WorkedExample, BranchSweepsTheWholeSolutionCircle) {
  // Any rotation about the P_f–Q_f axis with P and Q pinned solves the problem: build one by hand
  // and check the branch contains it.
  Problem p = workedExample();
  Solution s = solve(p, builtinRegistry());
  Eigen::Matrix4d eq17;
  eq17 << 0, -1, 0, 5, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  Isometry3d X0(eq17);
  const Vector3d Pf(0, 0, 3), axis(-1, 0, 0);
  for (double phi : {0.3, 1.7, -2.9}) {
    Isometry3d spin = Isometry3d::Identity();
    spin.linear() = Eigen::AngleAxisd(phi, axis).toRotationMatrix();
    spin.translation() = Pf - spin.linear() * Pf;
    Isometry3d X = spin * X0;
    ASSERT_LT(worstViolation(p, X), 1e-12);
    EXPECT_TRUE(someBranchContains(s, X)) << poseText(X);
  }
}

TEST(WorkedExample, RulesThatFireAreNamed) {
  Solution s = solve(workedExample(), builtinRegistry());
  ASSERT_GE(s.rules.size(), 2u);
  EXPECT_STREQ(s.ruleName(0), "pl+pl/lines-meet");
  EXPECT_STREQ(s.ruleName(1), "pp+pp/equal-span");
}

// A Solution names its rules after the Registry that solved it is gone (it shares the registry's
// name table): the names read afterwards are those the registry gave while it lived. (Under
// ASan a name pointing into the destroyed registry would be a use after free.)
TEST(WorkedExample, RuleNamesOutliveTheRegistry) {
  auto registry = std::make_unique<Registry>();
  registerBuiltins(*registry);
  registry->freeze();
  Solution s = solve(workedExample(), *registry);
  ASSERT_GE(s.rules.size(), 2u);
  std::vector<std::string> named;
  for (const RuleCaseId& id : s.rules)
    named.push_back(registry->rules()[id.rule].firedName(id.fired));
  registry.reset();
  ASSERT_EQ(s.ruleNames().size(), named.size());
  std::size_t i = 0;
  for (const char* name : s.ruleNames()) EXPECT_EQ(name, named[i++]);
  EXPECT_EQ(named[0], "pl+pl/lines-meet");
}

}  // namespace
}  // namespace relpos::test
