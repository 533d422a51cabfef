// Single range (min/max) constraints built around a known pose (Somani 004 Table III): every kind
// of distance and angle range solves, with one more DOF than its exact counterpart (the bounded
// distance or angle becomes a parameter), contains the known pose, and every sampled pose stays
// within the range. One-sided ranges too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>

#include "evaluator.hpp"
#include "local_dof.hpp"
#include "random_problems.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

// Turns the last constraint of kp into a range around its value (two-sided or one-sided, within
// what the spec accepts).
void widenLast(KnownProblem& kp, const SingleKind& kind, Rng& rng, int sides) {
  InputConstraint& c = kp.problem.constraints.back();
  const std::string type = kind.type;
  const double v = c.value;
  c.has_value = false;
  c.min = -std::numeric_limits<double>::infinity();
  c.max = std::numeric_limits<double>::infinity();
  const bool plane = kind.fixed == FeatureKind::kPlane || kind.mobile == FeatureKind::kPlane;
  const bool line_plane = kind.fixed != kind.mobile;
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
  if ((type == "distance" || type == "skew-distance") && !plane) lo = 0.0;
  if (type == "angle") lo = line_plane ? -kPi / 2 : 0.0, hi = line_plane ? kPi / 2 : kPi;
  if (sides != 2) c.min = std::max(lo, v - rng.uniform(0.05, 0.4));
  if (sides != 1) c.max = std::min(hi, v + rng.uniform(0.05, 0.4));
}

bool rangeable(const SingleKind& k) {
  const std::string t = k.type;
  return t == "distance" || t == "angle" || t == "skew-distance";
}

// Pairs with ranges (a range and an exact constraint, or two ranges), on shared or fresh mobile
// features: never inconsistent, never a violating pose, the known pose always on a branch.
TEST(RandomRanges, PairsWithRanges) {
  Rng rng(606);
  const auto& kinds = singleKinds();
  int solved = 0, total = 0, dof_checked = 0;
  for (std::size_t i = 0; i < kinds.size(); ++i)
    for (std::size_t j = i; j < kinds.size(); ++j) {
      if (!rangeable(kinds[i])) continue;
      for (int variant = 0; variant < 2; ++variant, ++total) {
        const bool grid = variant == 1;
        KnownProblem kp = emptyKnownProblem(rng, grid);
        addConstraint(kp, kinds[i], rng, grid);
        widenLast(kp, kinds[i], rng, total % 3);
        NamedFeature copy = kp.problem.mobile.features.back();
        addConstraint(kp, kinds[j], rng, grid, variant == 1 ? &copy : nullptr);
        if (rangeable(kinds[j]) && total % 2) widenLast(kp, kinds[j], rng, (total / 2) % 3);
        SCOPED_TRACE(std::string(kinds[i].label) + " (range) + " + kinds[j].label);
        ASSERT_LT(worstViolation(kp.problem, kp.X_WM_star), 1e-9);
        Solution s = solve(kp.problem, builtinRegistry());
        ASSERT_NE(s.status, Status::kInconsistent) << s.message;
        if (s.status != Status::kSolved) continue;
        ++solved;
        std::string where;
        EXPECT_LT(worstSampledViolation(kp.problem, s, 16, 700 + total, &where), 1e-8) << where;
        // An answer not proven complete (the numeric stage's charts, docs/spec.md §8.7) may miss
        // the known pose: each of its branches is checked above, its list need not be whole.
        if (!s.complete) continue;
        EXPECT_TRUE(someBranchContains(s, kp.X_WM_star))
            << describeBranches(s) << "\nknown pose " << poseText(kp.X_WM_star);
        if (!grid) {
          // The branch through the known pose has the local dimension there (ranges inactive
          // inside their bounds), measured independently.
          EXPECT_EQ(dofOfBranchesContaining(s, kp.X_WM_star), localDof(kp.problem, kp.X_WM_star))
              << describeBranches(s);
          ++dof_checked;
        }
      }
    }
  std::printf("[range pairs] solved %d of %d (%.1f%%), DOF checked %d\n", solved, total,
              100.0 * solved / total, dof_checked);
}

void runRanges(bool grid, std::uint64_t seed) {
  Rng rng(seed);
  int n = 0;
  for (const SingleKind& kind : singleKinds()) {
    if (!rangeable(kind)) continue;
    for (int k = 0; k < 12; ++k, ++n) {
      KnownProblem kp = emptyKnownProblem(rng, grid);
      addConstraint(kp, kind, rng, grid);
      widenLast(kp, kind, rng, k % 3);  // two-sided, only min, or only max
      const InputConstraint& c = kp.problem.constraints.back();
      SCOPED_TRACE(std::string(kind.label) + " range [" + std::to_string(c.min) + ", " +
                   std::to_string(c.max) + "] #" + std::to_string(k));
      ASSERT_LT(worstViolation(kp.problem, kp.X_WM_star), 1e-9);
      Solution s = solve(kp.problem, builtinRegistry());
      ASSERT_EQ(s.status, Status::kSolved) << s.message;
      ASSERT_EQ(static_cast<int>(s.branches.size()), kind.branches) << describeBranches(s);
      for (const Branch& b : s.branches) EXPECT_EQ(b.manifold->dof(), kind.dof + 1);
      EXPECT_TRUE(someBranchContains(s, kp.X_WM_star))
          << describeBranches(s) << "\nknown pose " << poseText(kp.X_WM_star);
      std::string where;
      EXPECT_LT(worstSampledViolation(kp.problem, s, 30, seed + n, &where), 1e-9) << where;
    }
  }
}

TEST(RandomRanges, GenericGeometry) { runRanges(false, 404); }
TEST(RandomRanges, AxisAlignedIntegerGeometry) { runRanges(true, 505); }

TEST(Ranges, NearestProjectsIntoTheRange) {
  // A point 0.1 to 0.3 above a plane, initially 1 above: nearest is 0.3 above, rotation kept.
  Problem p;
  p.addFixedFeature("floor", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "floor", "P", 0.0);
  p.constraints[0].has_value = false;
  p.constraints[0].min = 0.1;
  p.constraints[0].max = 0.3;
  p.mobile.pose.translation() = Vector3d(0.5, -0.2, 1.0);
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  ASSERT_EQ(s.branches.size(), 1u);
  EXPECT_EQ(s.branches[0].manifold->describe(), "rotation Free, translation Box");
  NearestPose n = nearestOnBranch(s.branches[0], p.mobile.pose);
  EXPECT_LT((n.pose.translation() - Vector3d(0.5, -0.2, 0.3)).norm(), 1e-9);
  EXPECT_NEAR(n.distance, 0.7, 1e-9);
  // Already inside: the pose itself.
  p.mobile.pose.translation() = Vector3d(0.5, -0.2, 0.2);
  EXPECT_NEAR(nearestOnBranch(s.branches[0], p.mobile.pose).distance, 0.0, 1e-12);
}

}  // namespace
}  // namespace relpos::test
