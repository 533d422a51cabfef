// The separable matcher (manifolds/src/separable_matcher.cpp) called directly on constraint sets:
// sets it matches (each branch checked against the set's constraints, evaluated here), sets it
// proves inconsistent (naming the sources), sets it defers (derived sets for each rotation) and
// sets it leaves to others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::test {
namespace {

MatchFn separableMatcher() {
  for (const MatcherInfo& m : builtinRegistry().matchers())
    if (m.name == "separable") return m.fn;
  return nullptr;
}

struct MatchRun {
  MatchResult result;
  Solution out;
  SourceMask conflict = 0;
  std::vector<ConstraintSet> deferred;
};

MatchRun match(const ConstraintSet& set, bool can_defer = false) {
  MatchRun run;
  const Tolerance tol;
  run.out.clear();
  run.deferred.reserve(64);  // BranchSink::defer never reallocates
  BranchSink sink(run.out.branches, 64, can_defer ? &run.deferred : nullptr);
  MatchContext ctx{set, tol, sink};
  run.result = separableMatcher()(ctx, nullptr);
  run.conflict = ctx.conflict;
  return run;
}

// The angle between R u_m and u_f, minus the constraint's: 0 when it holds.
double angleError(const Fundamental& f, const Matrix3d& R) {
  return std::abs(angleBetween(R * f.p, f.q) - f.value());
}

Params middleParams(const Manifold& m, Rng& rng) {
  Params t{};
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    const double lo = std::isfinite(p.min) ? p.min : -2, hi = std::isfinite(p.max) ? p.max : 2;
    t[i] = rng.uniform(lo, hi);
  }
  return t;
}

TEST(SeparableMatcher, OneParallelAndAPointGiveOneSpinAboutIt) {
  Rng rng(1);
  ConstraintSet set;
  const Fundamental par = Fundamental::angle(rng.unit(), rng.unit(), 0.0, 1);
  const Fundamental pin = Fundamental::pointPoint(rng.point(), rng.point(), 0.0, 2);
  set.add(par);
  set.add(pin);
  MatchRun run = match(set);
  ASSERT_EQ(run.result, MatchResult::kMatched);
  ASSERT_EQ(run.out.branches.size(), 1u);
  const Manifold& m = *run.out.branches[0].manifold;
  EXPECT_EQ(m.describe(), "rotation OneParallel, translation Point");
  EXPECT_EQ(m.dof(), 1);
  for (int k = 0; k < 20; ++k) {
    const Isometry3d X = m.pose(middleParams(m, rng));
    EXPECT_LT(angleError(par, X.linear()), 1e-9);
    EXPECT_LT((X * pin.p - pin.q).norm(), 1e-9);
  }
}

TEST(SeparableMatcher, ThreeAnglesOnRightTrihedraGiveRotationsThatMeetThemAll) {
  Rng rng(2);
  // Two right trihedra and the angles a rotation R_true makes between them: R_true is among
  // the answers.
  const Matrix3d M = axisAngle(rng.unit(), 1.0), F = axisAngle(rng.unit(), -2.0);
  const Matrix3d R_true = axisAngle(rng.unit(), 0.9);
  ConstraintSet set;
  std::vector<Fundamental> fs;
  for (int k = 0; k < 3; ++k) {
    const double alpha = angleBetween(R_true * M.col(k), F.col(k));
    fs.push_back(Fundamental::angle(M.col(k), F.col(k), alpha, SourceMask{1u} << k));
    set.add(fs.back());
  }
  MatchRun run = match(set);
  ASSERT_EQ(run.result, MatchResult::kMatched);
  ASSERT_GE(run.out.branches.size(), 1u);
  ASSERT_LE(run.out.branches.size(), 8u);
  double nearest_true = 1e300;
  for (const Branch& b : run.out.branches) {
    EXPECT_EQ(b.manifold->describe(), "rotation Fixed, translation R3");
    nearest_true =
        std::min(nearest_true, rotationDistance(b.manifold->pose(Params{}).linear(), R_true));
    const Matrix3d R = b.manifold->pose(Params{}).linear();
    for (const Fundamental& f : fs) EXPECT_LT(angleError(f, R), 1e-9);
  }
  EXPECT_LT(nearest_true, 1e-9);
  // Different rotations: none listed twice.
  for (std::size_t i = 0; i < run.out.branches.size(); ++i)
    for (std::size_t j = i + 1; j < run.out.branches.size(); ++j)
      EXPECT_GT(rotationDistance(run.out.branches[i].manifold->pose(Params{}).linear(),
                                 run.out.branches[j].manifold->pose(Params{}).linear()),
                1e-6);
}

TEST(SeparableMatcher, TwoParallelismsAtDifferentAnglesAreInconsistent) {
  ConstraintSet set;
  // Mobile vectors 90° apart, fixed ones 45° apart: no rotation takes one pair onto the other.
  set.add(Fundamental::angle(Vector3d::UnitX(), Vector3d::UnitX(), 0.0, 1));
  set.add(Fundamental::angle(Vector3d::UnitY(), Vector3d(1, 1, 0).normalized(), 0.0, 4));
  MatchRun run = match(set);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{5});
  EXPECT_TRUE(run.out.branches.empty());
}

TEST(SeparableMatcher, TwoAnglesNoRotationMeetsAreInconsistent) {
  ConstraintSet set;
  // R z within 0.1 rad of z leaves R x within 0.1 of horizontal: at least 1.1 rad from a fixed
  // vector 0.3 rad from z, never 0.2 from it.
  const Vector3d w(0.0, std::sin(0.3), std::cos(0.3));
  set.add(Fundamental::angle(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.1, 1));
  set.add(Fundamental::angle(Vector3d::UnitX(), w, 0.2, 2));
  MatchRun run = match(set);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{3});
}

TEST(SeparableMatcher, AFixedRotationWithALineDistanceIsDeferred) {
  Rng rng(3);
  const Matrix3d R = axisAngle(rng.unit(), 0.8);
  ConstraintSet set;
  set.add(Fundamental::angle(Vector3d::UnitX(), R.col(0), 0.0, 1));
  set.add(Fundamental::angle(Vector3d::UnitY(), R.col(1), 0.0, 2));
  // A line-line distance is mixed until the rotation fixes the mobile line's direction.
  set.add(Fundamental::lineLine(rng.point(), rng.unit(), rng.point(), rng.unit(), 0.5, 0.5, 4));
  EXPECT_EQ(match(set).result, MatchResult::kNoMatch);  // no deferral offered: left to others
  MatchRun run = match(set, true);
  ASSERT_EQ(run.result, MatchResult::kDeferred);
  EXPECT_TRUE(run.out.branches.empty());
  EXPECT_EQ(run.deferred.size(), 2u);  // the two sides of the distance (derived_sets_test.cpp)
}

// The solver hands a set holding a plugin's kind to plugins' matchers only: with the built-ins
// alone nothing matches it (it is never solved as if the custom constraint were not there).
TEST(SeparableMatcher, APluginKindIsLeftToThePlugin) {
  ConstraintSet set;
  set.clear();
  Fundamental f = Fundamental::pointPoint(Vector3d::Zero(), Vector3d::Zero(), 0.0, 1);
  f.kind = FundamentalKind::kCustom;
  set.add(f);
  Workspace ws;
  Solution s;
  solveConstraintSet(set, Tolerance(), builtinRegistry(), SolverOptions(), ws, s);
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_NE(s.message.find("no solution manifold matches"), std::string::npos) << s.message;
}

// An angle range [lo, hi] on (u_m, u_f).
Fundamental angleRange(const Vector3d& u_m, const Vector3d& u_f, double lo, double hi,
                       SourceMask s) {
  Fundamental f = Fundamental::angle(u_m, u_f, lo, s);
  f.lo = std::max(0.0, lo);
  f.hi = std::min(kPi, hi);
  return f;
}

// How far R breaks the (ranged) angle constraint f: 0 when it holds.
double rangeError(const Fundamental& f, const Matrix3d& R) {
  const double a = angleBetween(R * f.p, f.q);
  return std::max({0.0, f.lo - a, a - f.hi});
}

// Matches a ranged rotational set built around rotation R_true: every branch's sampled rotations
// meet every constraint, and R_true lies on some branch.
void expectRangedSet(const ConstraintSet& set, const Matrix3d& R_true, const char* manifold,
                     Rng& rng, int* branches = nullptr) {
  MatchRun run = match(set);
  ASSERT_EQ(run.result, MatchResult::kMatched);
  ASSERT_FALSE(run.out.branches.empty());
  if (branches) *branches = static_cast<int>(run.out.branches.size());
  double nearest = 1e9;
  for (const Branch& b : run.out.branches) {
    const Manifold& m = *b.manifold;
    EXPECT_NE(m.describe().find(manifold), std::string::npos) << m.describe();
    for (int k = 0; k < 20; ++k) {
      const Matrix3d R = m.pose(middleParams(m, rng)).linear();
      for (const Fundamental& f : set.rotational) EXPECT_LT(rangeError(f, R), 1e-9);
    }
    Isometry3d X = Isometry3d::Identity();
    X.linear() = R_true;
    nearest = std::min(nearest, rotationDistance(m.pose(m.project(X)).linear(), R_true));
  }
  EXPECT_LT(nearest, 1e-7) << "the rotation the set was built around is on no branch";
}

// Two ranges on one mobile vector (a torch's work and travel angles), one of them possibly
// exact: the vector's directions in both bands, the spin about it free (TwoAngleMinMax).
TEST(SeparableMatcher, TwoRangesOnOneVectorHoldEveryRotationInBoth) {
  Rng rng(21);
  int two = 0;
  for (int i = 0; i < 100; ++i) {
    const Matrix3d R = rng.pose().linear();
    const Vector3d m = rng.unit(), u1 = rng.unit(), u2 = rng.unit();
    const double a = angleBetween(R * m, u1), b = angleBetween(R * m, u2);
    ConstraintSet set;
    const bool exact = i % 4 == 0;
    set.add(exact ? Fundamental::angle(m, u1, a, 1)
                  : angleRange(m, u1, a - rng.uniform(0, 0.4), a + rng.uniform(0, 0.4), 1));
    // The second on −m half of the time: the angle of −m is π minus m's.
    const bool flip = i % 2 == 1;
    const double bb = flip ? kPi - b : b;
    set.add(angleRange(flip ? Vector3d(-m) : m, u2, bb - rng.uniform(0.01, 0.4),
                       bb + rng.uniform(0.01, 0.4), 2));
    int branches = 0;
    expectRangedSet(set, R, "TwoAngleMinMax", rng, &branches);
    two += branches == 2;
  }
  EXPECT_GT(two, 50);  // both sides of the plane of u1 and u2, usually
}

// A parallelism and a range on another vector (a keyway within ±10°): the spin on one or two
// arcs; a range on the spin axis itself is met always or never.
TEST(SeparableMatcher, AParallelismAndARangeOnAnotherVectorSpinOverArcs) {
  Rng rng(22);
  for (int i = 0; i < 100; ++i) {
    const Matrix3d R = rng.pose().linear();
    const Vector3d um = rng.unit(), vm = rng.unit(), vf = rng.unit();
    const double b = angleBetween(R * vm, vf);
    ConstraintSet set;
    set.add(Fundamental::angle(um, R * um, 0.0, 1));
    set.add(angleRange(vm, vf, b - rng.uniform(0, 0.3), b + rng.uniform(0.01, 0.3), 2));
    expectRangedSet(set, R, "OneParallel", rng);
  }
  // On the axis: 30° from the fixed vector for every spin.
  ConstraintSet kept, broken;
  const Vector3d tilted(0.0, 0.5, std::sqrt(0.75));
  for (ConstraintSet* s : {&kept, &broken})
    s->add(Fundamental::angle(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.0, 1));
  kept.add(angleRange(Vector3d::UnitZ(), tilted, 0.4, 0.6, 2));
  broken.add(angleRange(Vector3d::UnitZ(), tilted, 0.6, 0.8, 2));
  MatchRun k = match(kept);
  ASSERT_EQ(k.result, MatchResult::kMatched);
  ASSERT_EQ(k.out.branches.size(), 1u);
  EXPECT_TRUE(k.out.branches[0].manifold->parameter(0).periodic);
  MatchRun b = match(broken);
  EXPECT_EQ(b.result, MatchResult::kInconsistent);
  EXPECT_EQ(b.conflict, SourceMask{3});
}

TEST(SeparableMatcher, RangesNoRotationMeetsAreInconsistent) {
  // z within 10° of z and within 10° of x: the bands do not meet.
  ConstraintSet bands;
  bands.add(angleRange(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.0, 0.17, 1));
  bands.add(angleRange(Vector3d::UnitZ(), Vector3d::UnitX(), 0.0, 0.17, 2));
  MatchRun run = match(bands);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{3});
  // Spinning z about z keeps x horizontal: never within 10° of z.
  ConstraintSet spin;
  spin.add(Fundamental::angle(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.0, 1));
  spin.add(angleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.0, 0.17, 4));
  run = match(spin);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{5});
  // Two ranges on one axis that do not overlap.
  ConstraintSet axis;
  axis.add(angleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.2, 0.4, 1));
  axis.add(angleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.5, 0.7, 2));
  EXPECT_EQ(match(axis).result, MatchResult::kInconsistent);
}

// An exact angle and a range on another vector (a jaw across a can's axis, the approach within
// 30° of vertical): the cone's spin on arcs, φ where they exist (AngleWithRange).
TEST(SeparableMatcher, AnAngleAndARangeOnAnotherVectorHoldEveryRotationInBoth) {
  Rng rng(23);
  for (int i = 0; i < 100; ++i) {
    const Matrix3d R = rng.pose().linear();
    const Vector3d um = rng.unit(), uf = rng.unit(), vm = rng.unit(), vf = rng.unit();
    const double a = angleBetween(R * um, uf), b = angleBetween(R * vm, vf);
    if (a < 0.05 || a > kPi - 0.05) continue;  // a parallelism: another case
    ConstraintSet set;
    set.add(Fundamental::angle(um, uf, a, 1));
    set.add(angleRange(vm, vf, b - rng.uniform(0, 0.4), b + rng.uniform(0.01, 0.4), 2));
    expectRangedSet(set, R, "AngleWithRange", rng);
  }
  // z at 90° from z never brings x within 10° of z... unless x turns up: it does (x can be z).
  // z at 30° from z keeps x at least 60° from z: a range of 0-20° is out of reach.
  ConstraintSet set;
  set.add(Fundamental::angle(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.5236, 1));
  set.add(angleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.0, 0.35, 2));
  MatchRun run = match(set);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{3});
}

// How far pose X breaks translational constraint f (a point-point distance, or a mobile point on
// a fixed plane): 0 when it holds.
double translationError(const Fundamental& f, const Isometry3d& X) {
  const Vector3d p = X * f.p;
  if (f.kind == FundamentalKind::kPointPoint) return std::abs((p - f.q).norm() - f.value());
  return std::abs((p - f.q).dot(f.d));
}

// Two distances on two mobile points, or a distance and a point on a plane (a fingertip at a
// reach and the other on the table): the rotations for which the spheres (sphere and plane) meet,
// and the circle where they do (translation Circle); with a parallelism, the spin's arcs.
TEST(SeparableMatcher, TwoMobilePointsOnSpheresOrAPlaneGiveACircle) {
  Rng rng(24);
  int banded = 0;
  for (int i = 0; i < 200; ++i) {
    const Isometry3d X = rng.pose();
    const Vector3d p1 = rng.point(), p2 = rng.point(), a = rng.point();
    ConstraintSet set;
    const Fundamental f1 = Fundamental::pointPoint(p1, a, (X * p1 - a).norm(), 1);
    Fundamental f2;
    if (i % 2 == 0) {
      const Vector3d b = rng.point();
      f2 = Fundamental::pointPoint(p2, b, (X * p2 - b).norm(), 2);
    } else {
      const Vector3d n = rng.unit();
      f2 = Fundamental::pointPlane(Side::kMobile, p2, X * p2, n, 0.0, 2);
    }
    set.add(f1);
    set.add(f2);
    if (i % 4 == 1) set.add(Fundamental::angle(Vector3d::UnitZ(), X.linear().col(2), 0.0, 4));
    MatchRun run = match(set);
    ASSERT_EQ(run.result, MatchResult::kMatched) << "i " << i;
    double nearest = 1e9;
    for (const Branch& b : run.out.branches) {
      const Manifold& m = *b.manifold;
      EXPECT_NE(m.describe().find("translation Circle"), std::string::npos) << m.describe();
      banded += m.describe().find("rotation Free") == std::string::npos;
      for (int k = 0; k < 10; ++k) {
        const Isometry3d Y = m.pose(middleParams(m, rng));
        EXPECT_LT(translationError(f1, Y), 1e-9) << "i " << i;
        EXPECT_LT(translationError(f2, Y), 1e-9) << "i " << i;
      }
      nearest = std::min(nearest, poseDistance(m.pose(m.project(X)), X));
    }
    EXPECT_LT(nearest, 1e-7) << "the pose the set was built around is on no branch, i " << i;
  }
  EXPECT_GT(banded, 50);
  // Spheres 0.1 about points 5 apart, on mobile points 1 apart: they never meet.
  ConstraintSet never;
  never.add(Fundamental::pointPoint(Vector3d::Zero(), Vector3d::Zero(), 0.1, 1));
  never.add(Fundamental::pointPoint(Vector3d::UnitX(), Vector3d(5, 0, 0), 0.1, 2));
  MatchRun run = match(never);
  EXPECT_EQ(run.result, MatchResult::kInconsistent);
  EXPECT_EQ(run.conflict, SourceMask{3});
}

// Two ranges on different mobile vectors have no closed form yet: left to others.
TEST(SeparableMatcher, TwoRangesOnTwoVectorsAreLeftToOthers) {
  ConstraintSet set;
  set.add(angleRange(Vector3d::UnitZ(), Vector3d::UnitZ(), 0.1, 0.3, 1));
  set.add(angleRange(Vector3d::UnitX(), Vector3d::UnitY(), 0.4, 0.9, 2));
  EXPECT_EQ(match(set).result, MatchResult::kNoMatch);
}

TEST(SeparableMatcher, AnEmptySetIsEveryPose) {
  MatchRun run = match(ConstraintSet{});
  ASSERT_EQ(run.result, MatchResult::kMatched);
  ASSERT_EQ(run.out.branches.size(), 1u);
  EXPECT_EQ(run.out.branches[0].manifold->describe(), "rotation Free, translation R3");
  EXPECT_EQ(run.out.branches[0].manifold->dof(), 6);
}

}  // namespace
}  // namespace relpos::test
