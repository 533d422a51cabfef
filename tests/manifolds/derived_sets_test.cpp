// The derived sets (manifolds/src/derived_sets.cpp), reached through the separable matcher's
// deferral: once the rotation is fixed, every translational constraint re-anchored to the mobile
// origin; once it spins about a fixed line, the set flagged to be turned about it. A pose that
// satisfies the original set satisfies some derived set, evaluated here from the definitions.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "constraint_measure.hpp"
#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/core/solution.hpp"

namespace relpos::test {
namespace {

std::vector<ConstraintSet> deferredSets(const ConstraintSet& set, MatchResult* result) {
  std::vector<ConstraintSet> out;
  out.reserve(64);  // BranchSink::defer never reallocates
  Solution solution;
  const Tolerance tol;
  BranchSink sink(solution.branches, 64, &out);
  MatchContext ctx{set, tol, sink};
  for (const MatcherInfo& m : builtinRegistry().matchers())
    if (m.name == "separable") *result = m.fn(ctx, m.context);
  return out;
}

double worstSetViolation(const ConstraintSet& set, const Isometry3d& X) {
  double v = 0.0;
  for (const Fundamental& f : set.translational)
    v = std::max(v, violation(f, X.linear(), X.translation()));
  return v;
}

TEST(DerivedSets, ReanchoredSetsHoldWhereTheOriginalDoes) {
  Rng rng(21);
  for (int trial = 0; trial < 50; ++trial) {
    const Isometry3d X = rng.pose();
    const Matrix3d& R = X.linear();
    ConstraintSet set;
    set.add(Fundamental::angle(Vector3d::UnitX(), R.col(0), 0.0, 1));
    set.add(Fundamental::angle(Vector3d::UnitY(), R.col(1), 0.0, 2));
    // Constraints that hold at X, of both roles, with points away from the mobile origin.
    const Vector3d p = rng.point(), a = rng.point(), d = rng.unit();
    Fundamental pl = Fundamental::pointLine(Side::kFixed, X * p, a, d, 0.0, 4);
    pl.lo = pl.hi = measure(pl, R, X.translation());
    set.add(pl);
    const Vector3d n = rng.unit();
    Fundamental plane = Fundamental::pointPlane(Side::kMobile, p, rng.point(), n, 0.0, 8);
    plane.lo = measure(plane, R, X.translation()) - 0.4;
    plane.hi = plane.lo + 0.8;
    set.add(plane);
    MatchResult r = MatchResult::kNoMatch;
    const std::vector<ConstraintSet> derived = deferredSets(set, &r);
    ASSERT_EQ(r, MatchResult::kDeferred) << trial;
    ASSERT_EQ(derived.size(), 1u);
    const ConstraintSet& s = derived[0];
    ASSERT_EQ(s.translational.size(), 2u);
    for (const Fundamental& f : s.translational) {
      EXPECT_EQ(f.point_side, Side::kMobile);
      EXPECT_TRUE(f.p.isZero(0.0));
    }
    EXPECT_LT(worstSetViolation(s, X), 1e-9) << trial;
    // And not anywhere: moved along the plane's normal by more than its range, it breaks.
    Isometry3d Y = X;
    Y.translation() += 2.0 * n;
    EXPECT_GT(worstSetViolation(s, Y), 0.5) << trial;
  }
}

TEST(DerivedSets, ALineDistanceSplitsIntoOneSetPerSide) {
  Rng rng(22);
  for (int trial = 0; trial < 50; ++trial) {
    const Isometry3d X = rng.pose();
    ConstraintSet set;
    set.add(Fundamental::angle(Vector3d::UnitX(), X.linear().col(0), 0.0, 1));
    set.add(Fundamental::angle(Vector3d::UnitY(), X.linear().col(1), 0.0, 2));
    // The mobile line through a_m along u_m, at its distance from a fixed line at X.
    const Vector3d a_m = rng.point(), u_m = rng.unit(), a_f = rng.point(), d_f = rng.unit();
    Vector3d foot1, foot2;
    closestPointsOfLines(a_f, d_f, X * a_m, X.linear() * u_m, 1e-12, &foot1, &foot2);
    const double dist = (foot2 - foot1).norm();
    set.add(Fundamental::lineLine(a_m, u_m, a_f, d_f, dist, dist, 4));
    MatchResult r = MatchResult::kNoMatch;
    const std::vector<ConstraintSet> derived = deferredSets(set, &r);
    ASSERT_EQ(r, MatchResult::kDeferred);
    ASSERT_EQ(derived.size(), 2u);
    double best = 1e300;
    for (const ConstraintSet& s : derived) best = std::min(best, worstSetViolation(s, X));
    EXPECT_LT(best, 1e-8) << trial;  // X is on one side
  }
}

TEST(DerivedSets, ASpinWithConstraintsSymmetricAboutALineIsRevolved) {
  // One parallelism (spin about z) and a mobile point at distances from two fixed points on the
  // line through (1, 2, 0) along z: every constraint is symmetric about that line, and two
  // spheres are no translation shape of their own.
  ConstraintSet set;
  set.add(Fundamental::angle(Vector3d::UnitX(), Vector3d::UnitZ(), 0.0, 1));
  set.add(Fundamental::pointPoint(Vector3d(0.3, 0.1, 0.0), Vector3d(1, 2, 0), 0.7, 2));
  set.add(Fundamental::pointPoint(Vector3d(0.3, 0.1, 0.0), Vector3d(1, 2, 1), 0.9, 4));
  MatchResult r = MatchResult::kNoMatch;
  const std::vector<ConstraintSet> derived = deferredSets(set, &r);
  ASSERT_EQ(r, MatchResult::kDeferred);
  ASSERT_EQ(derived.size(), 1u);
  EXPECT_TRUE(derived[0].revolve);
  EXPECT_TRUE(derived[0].revolve_axis.isApprox(Vector3d::UnitZ()));
  EXPECT_LT((derived[0].revolve_point - Vector3d(1, 2, 0)).cross(Vector3d::UnitZ()).norm(), 1e-12);
  EXPECT_EQ(derived[0].rotational.size(), 2u);  // the rotation at φ = 0, as two parallelisms
}

}  // namespace
}  // namespace relpos::test
