// relpos::sampleParameters (docs/spec.md §2 `samples`): parameters within the manifold's bounds,
// an unbounded one within ±window of the centre's — also when the centre lies beyond a finite
// bound of a half-unbounded parameter (found by sampling about 0 a branch whose distance runs to
// at most −7e5 in a problem scaled ×1e6: the window [−1, −7e5] was reversed, and its samples left
// the branch).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::test {
namespace {

// A point kept at most −5 from a plane (a one-sided range): one branch whose offset parameter
// runs from −∞ to −5.
Problem belowAPlane() {
  Problem p;
  p.addFixedFeature("floor", Feature::makePlane(Vector3d::Zero(), Vector3d::UnitZ()));
  p.addMobileFeature("tip", Feature::makePoint(Vector3d::Zero()));
  p.addConstraint("distance", "floor", "tip", 0.0);
  InputConstraint& c = p.constraints.back();
  c.has_value = false;
  c.min = -std::numeric_limits<double>::infinity();
  c.max = -5.0;
  return p;
}

TEST(SampleParameters, AWindowBeyondAFiniteBoundIsMovedWithinIt) {
  const Problem p = belowAPlane();
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  int half_unbounded = 0;
  std::mt19937_64 rng(3);
  for (const Branch& b : s.branches) {
    const Manifold& m = *b.manifold;
    for (int i = 0; i < m.dof(); ++i) {
      const Parameter q = m.parameter(i);
      half_unbounded += std::isfinite(q.min) != std::isfinite(q.max);
    }
    for (const double centre : {0.0, 100.0, -100.0}) {
      Params c{};
      c.fill(centre);
      for (int k = 0; k < 50; ++k) {
        const Params t = sampleParameters(m, c, 1.0, rng);
        for (int i = 0; i < m.dof(); ++i) {
          EXPECT_GE(t[i], m.parameter(i).min) << "centre " << centre;
          EXPECT_LE(t[i], m.parameter(i).max) << "centre " << centre;
        }
        EXPECT_LT(worstViolation(p, m.pose(t)), 1e-9) << "centre " << centre;
      }
    }
  }
  EXPECT_GT(half_unbounded, 0) << "the problem no longer has the parameter this test is about";
}

}  // namespace
}  // namespace relpos::test
