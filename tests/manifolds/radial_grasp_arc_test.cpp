// RadialGraspManifold::nearestArc: the nearest pose of a radial grasp whose spin has a closed form
// lies on the shorter arc from X's azimuth to its approach direction's, so the one-angle search
// samples that arc alone. Held here to a dense scan of the whole turn, on random grasps: fingertips
// on either side of the mobile origin (the origin's radial offset positive over the radii, negative
// over them, or changing sign: no arc), radius and height ranges or values, random poses X.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "random_problems.hpp"
#include "relpos/core/geometry.hpp"
#include "relpos/manifolds/radial_grasp.hpp"

namespace relpos::test {
namespace {

using manifolds::RadialGraspManifold;
using manifolds::RadialGraspSpec;

RadialGraspSpec randomGrasp(Rng& rng) {
  RadialGraspSpec s;
  s.axis_point = rng.point(1.0);
  s.axis_dir = rng.unit();
  s.approach = rng.unit();
  // The mobile origin on the approach line (the spin's closed form), the tip before or behind it.
  s.tip = rng.uniform(-0.2, 0.2) * s.approach;
  s.r_lo = rng.uniform(0.0, 0.1);
  s.r_hi = rng.uniform(0.0, 1.0) < 0.3 ? s.r_lo : s.r_lo + rng.uniform(0.0, 0.1);
  s.has_height = rng.uniform(0.0, 1.0) < 0.7;
  s.plane_point = s.axis_point + rng.uniform(-0.5, 0.5) * s.axis_dir;
  s.plane_normal = s.axis_dir;
  s.h_lo = rng.uniform(-0.2, 0.2);
  s.h_hi = rng.uniform(0.0, 1.0) < 0.3 ? s.h_lo : s.h_lo + rng.uniform(0.0, 0.2);
  s.sigma = rng.uniform(0.0, 1.0) < 0.5 ? 1.0 : -1.0;
  return s;
}

Isometry3d randomPose(Rng& rng) {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(rng.uniform(0.0, kPi), rng.unit()).toRotationMatrix();
  X.translation() = rng.point(1.0);
  return X;
}

// The distance the search weighs at ψ, the other parameters in closed form.
double distanceAt(const RadialGraspManifold& m, const Isometry3d& X, double psi) {
  Params t{};
  t[0] = psi;
  return m.searchDistance(X, &t);
}

// The least of it on a grid of the whole turn.
double scannedLeast(const RadialGraspManifold& m, const Isometry3d& X, int steps) {
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < steps; ++k)
    least = std::min(least, distanceAt(m, X, -kPi + 2 * kPi * k / steps));
  return least;
}

TEST(RadialGraspArc, TheArcHoldsTheMinimumOfTheWholeTurn) {
  Rng rng(4242);
  int arcs = 0, none = 0;
  for (int k = 0; k < 400; ++k) {
    const RadialGraspManifold m(randomGrasp(rng));
    const Isometry3d X = randomPose(rng);
    int i = -1;
    double lo = 0.0, hi = 0.0;
    if (!m.nearestArc(X, &i, &lo, &hi)) {
      ++none;
      continue;
    }
    ++arcs;
    ASSERT_EQ(i, 0);
    ASSERT_LT(lo, hi);
    ASSERT_LE(hi - lo, kPi + 1e-5);
    // The least over the arc (a grid, its best point refined by golden sections: a grid point is
    // no minimum) is no more than any point of a grid over the whole turn.
    auto at = [&](double psi) { return distanceAt(m, X, psi); };
    const int steps = 4000;
    const double h = (hi - lo) / steps;
    int best = 0;
    double best_d = at(lo);
    for (int s = 1; s <= steps; ++s)
      if (const double d = at(lo + h * s); d < best_d) best = s, best_d = d;
    double a = lo + h * std::max(best - 1, 0), b = lo + h * std::min(best + 1, steps);
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 80; ++it) {
      const double c = b - g * (b - a), d = a + g * (b - a);
      if (at(c) < at(d))
        b = d;
      else
        a = c;
    }
    const double on_arc = std::min(best_d, at(0.5 * (a + b)));
    const double whole = scannedLeast(m, X, 8000);
    EXPECT_LE(on_arc, whole + 1e-12) << "grasp " << k;
  }
  // Both cases occur: the test says something about each.
  EXPECT_GT(arcs, 100);
  EXPECT_GT(none, 20);
}

// What the search answers with the arc is no farther than the whole turn's dense scan: the
// samples, 15° apart over the arc, and Brent's refinement find the nearest basin.
TEST(RadialGraspArc, TheNearestPoseIsNoFartherThanADenseScan) {
  Rng rng(977);
  int arcs = 0;
  for (int k = 0; k < 400; ++k) {
    const RadialGraspManifold m(randomGrasp(rng));
    const Isometry3d X = randomPose(rng);
    int i;
    double lo, hi;
    arcs += m.nearestArc(X, &i, &lo, &hi);
    const Params t = nearestParams(m, X);
    const double d = poseDistance(m.pose(t), X);
    const double whole = scannedLeast(m, X, 7200);
    EXPECT_LE(d, whole + 1e-9) << "grasp " << k;
  }
  EXPECT_GT(arcs, 100);
}

}  // namespace
}  // namespace relpos::test
