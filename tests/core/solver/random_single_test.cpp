// Randomised single-constraint problems built around a known pose (fixed seeds): each must come
// back solved, with the hand-derived DOF and branch count, containing the known pose, and with no
// sampled pose violating the constraint. Random and axis-aligned integer geometry.
#include <gtest/gtest.h>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

void runSingles(bool grid, std::uint64_t seed, int per_kind) {
  Rng rng(seed);
  int n = 0;
  for (const SingleKind& kind : singleKinds()) {
    for (int k = 0; k < per_kind; ++k, ++n) {
      KnownProblem kp = emptyKnownProblem(rng, grid);
      addConstraint(kp, kind, rng, grid);
      SCOPED_TRACE(std::string(kind.label) + " #" + std::to_string(k));
      ASSERT_LT(worstViolation(kp.problem, kp.X_WM_star), 1e-9) << "generator bug";
      Solution s = solve(kp.problem, builtinRegistry());
      ASSERT_EQ(s.status, Status::kSolved) << describeBranches(s);
      ASSERT_EQ(static_cast<int>(s.branches.size()), kind.branches) << describeBranches(s);
      for (const Branch& b : s.branches) EXPECT_EQ(b.manifold->dof(), kind.dof);
      EXPECT_TRUE(someBranchContains(s, kp.X_WM_star))
          << describeBranches(s) << "\nknown pose " << poseText(kp.X_WM_star);
      std::string where;
      EXPECT_LT(worstSampledViolation(kp.problem, s, 20, seed + n, &where), 1e-8) << where;
    }
  }
}

TEST(RandomSingle, GenericGeometry) { runSingles(false, 20261122, 12); }
TEST(RandomSingle, AxisAlignedIntegerGeometry) { runSingles(true, 424242, 12); }

}  // namespace
}  // namespace relpos::test
