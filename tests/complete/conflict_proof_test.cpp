// The numeric stage's proof of inconsistency and its conflicting subset (docs/spec.md §8.8):
// never proven where a pose exists (random problems built around a known pose, ranges whose
// edge is the known pose's value), and proven with exactly the conflicting constraints named on
// problems infeasible by construction — two reaches too far apart, two angle ranges to directions
// too far apart, two plane offsets of points too close — with constraints that do not take part
// around them, in moved, turned and scaled copies alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "conflict_search.hpp"
#include "chart_solve.hpp"
#include "evaluator.hpp"
#include "problem_transforms.hpp"
#include "ranged_problems.hpp"
#include "relpos/complete/stage.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool provenInconsistent(const Problem& p, int boxes) {
  std::vector<complete::detail::ConditionSystem> systems;
  std::string why;
  if (!complete::detail::buildConditionSystems(p, builtinRegistry(), &systems, &why)) return false;
  return complete::detail::proveConflict(systems, p.constraints.size(), toleranceOf(p), boxes)
      .proven;
}

// The value of constraint c at pose X (within its range): read through the violation of the
// same constraint with one exact value, its range's finite end.
double valueAt(InputConstraint c, const Problem& p, const Isometry3d& X) {
  const bool from_min = std::isfinite(c.min);
  const double end = from_min ? c.min : c.max;
  c.min = c.max = end;
  const double off = violation(c, p.fixed.pose, X);
  return from_min ? end + off : end - off;
}

// Every range of the problem with one end moved to the known pose's value: still feasible, by
// nothing.
Problem rangesAtTheirEdge(const KnownProblem& kp, Rng& rng) {
  Problem p = kp.problem;
  for (InputConstraint& c : p.constraints) {
    if (c.has_value || !(std::isfinite(c.min) || std::isfinite(c.max))) continue;
    const double v = valueAt(c, p, kp.X_WM_star);
    const bool move_min = std::isfinite(c.min) && (!std::isfinite(c.max) || rng.integer(0, 1));
    (move_min ? c.min : c.max) = v;
  }
  return p;
}

TEST(ConflictProof, NeverProvenWhereAPoseExists) {
  Rng rng(2216);
  int edges = 0;
  for (int i = 0; i < 200; ++i) {
    const KnownProblem kp = rangedProblem(rng, i);
    SCOPED_TRACE("problem " + std::to_string(i));
    EXPECT_FALSE(provenInconsistent(kp.problem, 1000));
    const Problem edge = rangesAtTheirEdge(kp, rng);
    if (!(worstViolation(edge, kp.X_WM_star) < 1e-12)) continue;  // a range read otherwise
    ++edges;
    EXPECT_FALSE(provenInconsistent(edge, 1000));
  }
  std::printf("[conflicts] 200 problems and %d with ranges at their edge not proven\n", edges);
  EXPECT_GT(edges, 150);
}

// Adds to p constraints that any pose nearly meets (they take no part in the conflict): an angle
// range of a mobile line, wide, and a one-sided plane offset of a mobile point, far.
void addBystanders(Problem& p, Rng& rng, int count) {
  for (int k = 0; k < count; ++k) {
    const std::string f = "by_f" + std::to_string(k), m = "by_m" + std::to_string(k);
    if (k % 2 == 0) {
      p.addFixedFeature(f, Feature::makeLine(rng.point(), rng.unit()));
      p.addMobileFeature(m, Feature::makeLine(rng.point(0.5), rng.unit()));
      p.addConstraint("angle", f, m);
      p.constraints.back().has_value = false;
      p.constraints.back().min = 0.0, p.constraints.back().max = 2.0;  // within ~115°
    } else {
      p.addFixedFeature(f, Feature::makePlane(rng.point(), rng.unit()));
      p.addMobileFeature(m, Feature::makePoint(rng.point(0.5)));
      p.addConstraint("distance", f, m);
      p.constraints.back().has_value = false;
      p.constraints.back().min = -50.0, p.constraints.back().max = kInf;
    }
  }
}

// The constraints at `a` and `b` conflict; `extra` bystanders go around them. Returns the
// problem with its constraints shuffled, and where the pair went.
struct Built {
  Problem problem;
  std::vector<int> pair;
};

Built shuffled(Problem p, Rng& rng) {
  const int n = static_cast<int>(p.constraints.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng.engine());
  Built b;
  b.problem = p;
  for (int i = 0; i < n; ++i) b.problem.constraints[i] = p.constraints[order[i]];
  for (int i = 0; i < n; ++i)
    if (order[i] < 2) b.pair.push_back(i);
  return b;
}

// Two mobile points each within reach of its own fixed point, the fixed points too far apart for
// both (by `gap`).
Problem reachesTooFarApart(Rng& rng, double gap) {
  Problem p;
  const Vector3d a = rng.point(0.5), b = rng.point(0.5);
  const double r1 = rng.uniform(0.2, 1.0), r2 = rng.uniform(0.2, 1.0);
  const Vector3d P = rng.point(), Q = P + (r1 + r2 + (a - b).norm() + gap) * rng.unit();
  p.addFixedFeature("P", Feature::makePoint(P));
  p.addFixedFeature("Q", Feature::makePoint(Q));
  p.addMobileFeature("a", Feature::makePoint(a));
  p.addMobileFeature("b", Feature::makePoint(b));
  p.addConstraint("distance", "P", "a");
  p.constraints.back().has_value = false;
  p.constraints.back().min = 0.0, p.constraints.back().max = r1;
  p.addConstraint("distance", "Q", "b");
  p.constraints.back().has_value = false;
  p.constraints.back().min = rng.uniform(0.0, 0.5) * r2, p.constraints.back().max = r2;
  return p;
}

// One mobile direction within α of one fixed direction and within β of another, the two more
// than α + β + gap apart.
Problem anglesTooFarApart(Rng& rng, double gap) {
  Problem p;
  const double alpha = rng.uniform(0.1, 0.8), beta = rng.uniform(0.1, 0.8);
  const double apart = std::min(kPi, alpha + beta + gap);
  const Vector3d f1 = rng.unit(), side = rng.perpendicular(f1);
  const Vector3d f2 = std::cos(apart) * f1 + std::sin(apart) * side;
  p.addFixedFeature("f1", Feature::makeLine(rng.point(), f1));
  p.addFixedFeature("f2", Feature::makeLine(rng.point(), f2));
  p.addMobileFeature("u", Feature::makeLine(rng.point(0.5), rng.unit()));
  p.addConstraint("angle", "f1", "u");
  p.constraints.back().has_value = false;
  p.constraints.back().min = 0.0, p.constraints.back().max = alpha;
  p.addConstraint("angle", "f2", "u");
  p.constraints.back().has_value = false;
  p.constraints.back().min = 0.0, p.constraints.back().max = beta;
  return p;
}

// Two mobile points a, b at offsets from one fixed plane whose ranges are further apart than
// |a − b| (by `gap`).
Problem offsetsTooFarApart(Rng& rng, double gap) {
  Problem p;
  const Vector3d a = rng.point(0.5), b = rng.point(0.5);
  p.addFixedFeature("floor", Feature::makePlane(rng.point(), rng.unit()));
  p.addMobileFeature("a", Feature::makePoint(a));
  p.addMobileFeature("b", Feature::makePoint(b));
  const double lo = rng.uniform(-1.0, 1.0), width = rng.uniform(0.05, 0.5);
  p.addConstraint("distance", "floor", "a");
  p.constraints.back().has_value = false;
  p.constraints.back().min = lo, p.constraints.back().max = lo + width;
  p.addConstraint("distance", "floor", "b");
  p.constraints.back().has_value = false;
  const double b_lo = lo + width + (a - b).norm() + gap;
  p.constraints.back().min = b_lo, p.constraints.back().max = b_lo + rng.uniform(0.05, 0.5);
  return p;
}

void expectThePairConflicts(Problem (*make)(Rng&, double), std::uint64_t seed) {
  Rng rng(seed);
  int proven = 0, copies = 0;
  for (int i = 0; i < 16; ++i) {
    Problem p = make(rng, rng.uniform(0.05, 0.3));
    addBystanders(p, rng, i % 3);
    const Built built = shuffled(p, rng);
    SCOPED_TRACE("problem " + std::to_string(i));
    const Solution s = solveByCharts(built.problem);
    if (s.status != Status::kInconsistent) {
      ADD_FAILURE() << s.message;
      continue;
    }
    EXPECT_TRUE(s.complete);
    EXPECT_EQ(s.conflicts, built.pair) << s.message;
    ++proven;
    for (const ProblemTransform& t : invarianceTransforms()) {
      const Solution c = solveByCharts(t.apply(built.problem));
      EXPECT_EQ(c.status, Status::kInconsistent) << t.label << ": " << c.message;
      EXPECT_EQ(c.conflicts, built.pair) << t.label;
      ++copies;
    }
  }
  std::printf("[conflicts] %d proven with their pair named, %d transformed copies\n", proven,
              copies);
}

TEST(ConflictProof, ReachesTooFarApartNameTheirPair) {
  expectThePairConflicts(reachesTooFarApart, 3);
}
TEST(ConflictProof, AnglesTooFarApartNameTheirPair) {
  expectThePairConflicts(anglesTooFarApart, 4);
}
TEST(ConflictProof, OffsetsTooFarApartNameTheirPair) {
  expectThePairConflicts(offsetsTooFarApart, 5);
}

// A conflict by less than the tolerance is no conflict: the same constructions with the gap a
// tenth of the tolerance (relative 1e-9 of the problem's size, and 1e-9 rad) are never proven.
TEST(ConflictProof, AGapWithinTheToleranceIsNotProven) {
  Rng rng(6);
  for (int i = 0; i < 30; ++i) {
    Problem (*make)(Rng&, double) = i % 3 == 0   ? reachesTooFarApart
                                    : i % 3 == 1 ? anglesTooFarApart
                                                 : offsetsTooFarApart;
    const Problem p = make(rng, 1e-10);
    SCOPED_TRACE("problem " + std::to_string(i));
    EXPECT_FALSE(provenInconsistent(p, 3000));
  }
}

// Two angle ranges on one mobile direction that overlap by 1e-7 rad (100 tolerances), the mobile
// direction at or within 1e-5 rad of an axis either way (where a rotation built to turn it onto
// z is least orthogonal): feasible, never proven inconsistent.
TEST(ConflictProof, OverlappingAngleRangesNearAnAxisAreNotProven) {
  Rng rng(7);
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0})
      for (double off : {0.0, 1e-6, 3e-6, 1e-5}) {
        const Vector3d e = sign * Vector3d::Unit(axis), side = Vector3d::Unit((axis + 1) % 3);
        const Vector3d u = (std::cos(off) * e + std::sin(off) * side).normalized();
        const Vector3d f1 = rng.unit(), across = rng.perpendicular(f1);
        const double apart = 0.9 - 1e-7;
        const Vector3d f2 = std::cos(apart) * f1 + std::sin(apart) * across;
        Problem p;
        p.addFixedFeature("f1", Feature::makeLine(Vector3d::Zero(), f1));
        p.addFixedFeature("f2", Feature::makeLine(Vector3d::UnitX(), f2));
        p.addMobileFeature("u", Feature::makeLine(Vector3d::Zero(), u));
        p.addConstraint("angle", "f1", "u");
        p.constraints.back().has_value = false;
        p.constraints.back().min = 0.0, p.constraints.back().max = 0.4;
        p.addConstraint("angle", "f2", "u");
        p.constraints.back().has_value = false;
        p.constraints.back().min = 0.0, p.constraints.back().max = 0.5;
        SCOPED_TRACE("axis " + std::to_string(axis) + " sign " + std::to_string(sign) + " off " +
                     std::to_string(off));
        EXPECT_FALSE(provenInconsistent(p, 6000));
      }
}

}  // namespace
}  // namespace relpos::test
