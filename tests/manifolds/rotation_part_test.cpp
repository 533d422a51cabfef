// Rotation parts checked against their defining constraints, independently of the matcher.
#include "relpos/manifolds/rotation_part.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "random_problems.hpp"

namespace relpos::test {
namespace {

using manifolds::RotationPart;
namespace rotation = manifolds::rotation;

TEST(RotationPart, OneParallelKeepsTheVectorParallel) {
  Rng rng(1);
  for (int i = 0; i < 100; ++i) {
    Vector3d um = rng.unit(), uf = rng.unit();
    RotationPart r = rotation::OneParallel(um, uf);
    double t[1] = {rng.uniform(-3, 3)};
    EXPECT_TRUE((r.rotation(t) * um).isApprox(uf, 1e-12));
  }
}

TEST(RotationPart, OneAngleKeepsTheAngle) {
  Rng rng(2);
  for (int i = 0; i < 100; ++i) {
    Vector3d um = rng.unit(), uf = rng.unit();
    double a = rng.uniform(0, 3.14159);
    RotationPart r = rotation::OneAngle(um, uf, a);
    double t[2] = {rng.uniform(-3, 3), rng.uniform(-3, 3)};
    EXPECT_NEAR(std::acos(std::min(1.0, (r.rotation(t) * um).dot(uf))), a, 1e-7);
  }
}

TEST(RotationPart, OneParallelProjectionIsTheClosestSpin) {
  // Brute force over φ agrees with the closed form.
  Rng rng(3);
  for (int i = 0; i < 50; ++i) {
    RotationPart r = rotation::OneParallel(rng.unit(), rng.unit());
    Matrix3d target = rng.pose().linear();
    double t[1];
    r.project(target, t);
    double best = 1e9;
    for (int k = 0; k < 3600; ++k) {
      double phi[1] = {-3.14159265 + k * 2 * 3.14159265 / 3600};
      best = std::min(best, rotationDistance(r.rotation(phi), target));
    }
    EXPECT_LE(rotationDistance(r.rotation(t), target), best + 1e-6);
  }
}

TEST(RotationPart, FreeProjectionRecoversRollPitchYaw) {
  RotationPart r = rotation::Free{};
  for (double pitch : {-1.5707963267948966, -0.4, 0.0, 1.2, 1.5707963267948966}) {
    double t[3] = {0.3, pitch, -2.0};
    Matrix3d R = r.rotation(t);
    double back[3];
    r.project(R, back);
    EXPECT_LT(rotationDistance(r.rotation(back), R), 1e-9) << pitch;
  }
}

TEST(RotationPart, AngleRangeKeepsTheAngleWithinItsBoundsAndProjectsBack) {
  Rng rng(4);
  for (int i = 0; i < 100; ++i) {
    const Vector3d um = rng.unit(), uf = rng.unit();
    const double lo = rng.uniform(0.1, 1.0), hi = lo + rng.uniform(0.1, 1.5);
    const RotationPart r = rotation::OneAngleRange(um, uf, lo, hi);
    ASSERT_EQ(r.dof(), 3);
    double t[3] = {rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(lo, hi)};
    const Matrix3d R = r.rotation(t);
    // The angle parameter is the angle itself (defining equation, evaluated here).
    EXPECT_NEAR(angleBetween(R * um, uf), t[2], 1e-9);
    double back[3];
    r.project(R, back);
    EXPECT_LT(rotationDistance(r.rotation(back), R), 1e-9);
    EXPECT_NEAR(back[2], t[2], 1e-9);
    // The spin about u_m is the second parameter: R = spinBase(t) R(u_m, t[1]).
    ASSERT_NE(r.spinAxis(), nullptr);
    EXPECT_LT(rotationDistance(r.spinBase(t) * axisAngle(um, t[1]), R), 1e-12);
  }
}

// Two angle constraints on random vectors, at the angles a random rotation makes (so that the
// set is not empty); *alpha and *beta receive them.
rotation::TwoAngle randomTwoAngle(Rng& rng, double* alpha, double* beta) {
  const Vector3d um = rng.unit(), uf = rng.unit(), vm = rng.unit(), vf = rng.unit();
  const Matrix3d R_true = rng.pose().linear();
  *alpha = angleBetween(R_true * um, uf), *beta = angleBetween(R_true * vm, vf);
  return rotation::TwoAngle(rotation::OneAngle(um, uf, *alpha), vm, vf, std::cos(*beta));
}

TEST(RotationPart, TwoAngleRotationsMeetBothAngles) {
  Rng rng(5);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    double alpha, beta;
    const rotation::TwoAngle shape = randomTwoAngle(rng, &alpha, &beta);
    const Vector3d &um = shape.u_m, &uf = shape.u_f, &vm = shape.v_m, &vf = shape.v_f;
    for (double sign : {1.0, -1.0}) {
      rotation::TwoAngle two = shape;
      two.sign = sign;
      const RotationPart r = two;
      for (int k = 0; k < 10; ++k) {
        double t[1] = {rng.uniform(-kPi, kPi)}, theta = 0.0;
        if (!two.theta(t[0], &theta)) continue;  // φ outside the valid set
        const Matrix3d R = r.rotation(t);
        EXPECT_NEAR(angleBetween(R * um, uf), alpha, 1e-7);
        EXPECT_NEAR(angleBetween(R * vm, vf), beta, 1e-7);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// A rotation of the branch projects back onto itself (docs/spec.md §2.6: the nearest pose of a
// branch holding the initial pose is that pose): φ over the whole turn, just past ±π, near the
// ends of ranges that reach beyond ±π. The scan of 64 steps alone missed minima narrower than a
// step (θ(φ) turning steeply, φ by a range's end) and did not join ±π.
TEST(RotationPart, TwoAngleProjectsItsOwnRotationsBack) {
  Rng rng(23);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    double alpha, beta;
    rotation::TwoAngle two = randomTwoAngle(rng, &alpha, &beta);
    two.sign = i % 2 == 0 ? 1.0 : -1.0;
    if (i % 3 == 1) {  // a range reaching beyond ±π
      two.phi_lo = rng.uniform(-4.0, 2.0);
      two.phi_hi = two.phi_lo + rng.uniform(0.05, 2 * kPi);
      two.phi_periodic = false;
    }
    const RotationPart r = two;
    for (int k = 0; k < 12; ++k) {
      double t[1];
      if (two.phi_periodic)
        t[0] = k < 2 ? (k == 0 ? -kPi + 1e-3 : kPi - 2e-3) : rng.uniform(-kPi, kPi);
      else
        t[0] = k < 2 ? (k == 0 ? two.phi_lo + 1e-3 : two.phi_hi - 1e-3)
                     : rng.uniform(two.phi_lo, two.phi_hi);
      double theta = 0.0, back[1] = {0.0};
      if (!two.theta(t[0], &theta)) continue;  // φ outside the valid set
      const Matrix3d R = r.rotation(t);
      r.project(R, back);
      EXPECT_LT(rotationDistance(r.rotation(back), R), 1e-9) << i << " " << t[0] << " " << back[0];
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

// A spin over an arc: every φ of the arc keeps the parallelism, the projection stays on the
// arc (the nearer end when the nearest spin is off it), and round-trips on it.
TEST(RotationPart, OneParallelOverAnArcStaysOnIt) {
  Rng rng(11);
  for (int i = 0; i < 100; ++i) {
    const Vector3d um = rng.unit(), uf = rng.unit();
    rotation::OneParallel spin(um, uf);
    spin.phi_lo = rng.uniform(-4.0, 2.0);
    spin.phi_hi = spin.phi_lo + rng.uniform(0.05, 5.0);
    spin.phi_periodic = false;
    const RotationPart r = spin;
    const Parameter p = r.parameter(0);
    EXPECT_EQ(p.min, spin.phi_lo);
    EXPECT_EQ(p.max, spin.phi_hi);
    EXPECT_FALSE(p.periodic);
    double t[1] = {rng.uniform(spin.phi_lo, spin.phi_hi)}, back[1];
    EXPECT_TRUE((r.rotation(t) * um).isApprox(uf, 1e-12));
    r.project(r.rotation(t), back);
    EXPECT_NEAR(back[0], t[0], 1e-9);
    // Any rotation projects onto the arc, at its nearest spin or an end.
    r.project(rng.pose().linear(), back);
    EXPECT_GE(back[0], spin.phi_lo);
    EXPECT_LE(back[0], spin.phi_hi);
  }
  EXPECT_DOUBLE_EQ(rotation::ontoArc(0.5, 0.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(rotation::ontoArc(0.5 + 2 * kPi, 0.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(rotation::ontoArc(1.2, 0.0, 1.0), 1.0);   // nearer the upper end
  EXPECT_DOUBLE_EQ(rotation::ontoArc(-0.2, 0.0, 1.0), 0.0);  // nearer the lower end
}

// Ranges of angles from two fixed directions: every parameter of the box gives a rotation whose
// m meets both ranges on the branch's side (the defining equations, evaluated here), the spin is
// the second parameter, and the projection round-trips. Boxes the triangle inequalities cut use
// β's place between its bounds; an exact α gives two parameters.
TEST(RotationPart, TwoAngleRangesMeetBothRangesAndProjectBack) {
  Rng rng(12);
  int fractions = 0, exact = 0, checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Vector3d m = rng.unit(), u1 = rng.unit(), u2 = rng.unit();
    double a_lo = rng.uniform(0.0, 2.5), a_hi = a_lo + rng.uniform(0.0, 0.8);
    if (i % 5 == 0) a_hi = a_lo;  // an exact angle
    const double b_lo = rng.uniform(0.0, 2.5), b_hi = b_lo + rng.uniform(0.05, 0.8);
    for (double side : {1.0, -1.0}) {
      const rotation::TwoAngleRange shape(m, u1, a_lo, std::min(a_hi, kPi), u2, b_lo,
                                          std::min(b_hi, kPi), side);
      if (shape.empty()) continue;
      const RotationPart r = shape;
      ASSERT_EQ(r.dof(), a_lo == a_hi ? 2 : 3);
      fractions += shape.fraction && r.dof() == 3;
      exact += r.dof() == 2;
      double t[3], back[3];
      for (int k = 0; k < r.dof(); ++k) {
        const Parameter p = r.parameter(k);
        ASSERT_LE(p.min, p.max) << p.name;
        t[k] = rng.uniform(p.min, p.max);
      }
      const Matrix3d R = r.rotation(t);
      const Vector3d d = R * m;
      const double a = angleBetween(d, u1), b = angleBetween(d, u2);
      EXPECT_GE(a, a_lo - 1e-9);
      EXPECT_LE(a, a_hi + 1e-9);
      EXPECT_GE(b, b_lo - 1e-9);
      EXPECT_LE(b, b_hi + 1e-9);
      EXPECT_GE(side * d.dot(u1.cross(u2)), -1e-9);
      ASSERT_NE(r.spinAxis(), nullptr);
      EXPECT_LT(rotationDistance(r.spinBase(t) * axisAngle(m, t[1]), R), 1e-12);
      r.project(R, back);
      EXPECT_LT(rotationDistance(r.rotation(back), R), 1e-7) << "i " << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(fractions, 20);
  EXPECT_GT(exact, 20);
}

// The two sides' branches hold every direction that meets both ranges: a random direction in
// both bands is on one of them (projection finds it).
TEST(RotationPart, TwoAngleRangesHoldEveryDirectionInBothBands) {
  Rng rng(13);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Vector3d m = rng.unit(), u1 = rng.unit(), u2 = rng.unit();
    const Vector3d d = rng.unit();
    const double a = angleBetween(d, u1), b = angleBetween(d, u2);
    const double a_lo = std::max(0.0, a - rng.uniform(0.0, 0.5)), a_hi = std::min(kPi, a + 0.3);
    const double b_lo = std::max(0.0, b - rng.uniform(0.0, 0.5)), b_hi = std::min(kPi, b + 0.2);
    double best = 1e9;
    for (double side : {1.0, -1.0}) {
      const rotation::TwoAngleRange shape(m, u1, a_lo, a_hi, u2, b_lo, b_hi, side);
      if (shape.empty()) continue;
      const RotationPart r = shape;
      Matrix3d R = Eigen::Quaterniond::FromTwoVectors(m, d).toRotationMatrix();
      double t[3];
      r.project(R, t);
      best = std::min(best, angleBetween(r.rotation(t) * m, d));
    }
    EXPECT_LT(best, 1e-7) << "i " << i;
    ++checked;
  }
  EXPECT_EQ(checked, 300);
}

// An exact angle and a range on another vector: every (φ, t) of the box keeps the first angle
// exact and the second within its range (both signs), and the projection round-trips.
TEST(RotationPart, AngleWithRangeMeetsBothAndProjectsBack) {
  Rng rng(14);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const Vector3d um = rng.unit(), uf = rng.unit(), vm = rng.unit(), vf = rng.unit();
    const Matrix3d R_true = rng.pose().linear();
    const double alpha = angleBetween(R_true * um, uf), beta = angleBetween(R_true * vm, vf);
    const double lo = std::max(0.0, beta - rng.uniform(0.05, 0.5));
    const double hi = std::min(kPi, beta + rng.uniform(0.05, 0.5));
    for (double sign : {1.0, -1.0}) {
      rotation::AngleWithRange shape(um, uf, alpha, vm, vf, lo, hi);
      shape.sign = sign;
      const RotationPart r = shape;
      for (int k = 0; k < 5; ++k) {
        double t[2] = {rng.uniform(-kPi, kPi), rng.uniform(0.0, 1.0)}, back[2];
        double theta0, in, out;
        shape.arc(t[0], &theta0, &in, &out);
        const Matrix3d R = r.rotation(t);
        EXPECT_NEAR(angleBetween(R * um, uf), alpha, 1e-7);
        // Where the range is reachable at this φ (the matcher keeps only those φ), it holds.
        if (std::cos(in) >= std::cos(out) + 1e-9) {
          const double b = angleBetween(R * vm, vf);
          EXPECT_GE(b, lo - 1e-7);
          EXPECT_LE(b, hi + 1e-7);
          r.project(R, back);
          EXPECT_LT(rotationDistance(r.rotation(back), R), 1e-6) << "i " << i;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(RotationPart, FixedIsTheNearestRotationAndHasNoParameters) {
  Rng rng(6);
  const Matrix3d R = rng.pose().linear();
  const RotationPart r = rotation::Fixed(R);
  EXPECT_EQ(r.dof(), 0);
  EXPECT_LT(rotationDistance(r.rotation(nullptr), R), 1e-12);
  EXPECT_LT(rotationDistance(r.baseRotation(), R), 1e-12);
  EXPECT_EQ(r.spinAxis(), nullptr);
}

// The shapes that say their projection is exact (projectsExactly: a fully separable branch
// then takes it as its nearest pose, nearest_global): no rotation sampled over the whole shape,
// nor about the projection, is nearer to the target in the geodesic angle. Targets: any rotation,
// and one a small turn off the shape (where the projection is nearly its own).
TEST(RotationPart, ExactProjectionsAreTheNearestRotations) {
  Rng rng(12);
  std::vector<RotationPart> shapes;
  for (int i = 0; i < 12; ++i) {
    const Vector3d um = rng.unit(), uf = rng.unit();
    shapes.emplace_back(rotation::OneParallel(um, uf));
    rotation::OneParallel arc(um, uf);
    arc.phi_lo = rng.uniform(-3.0, 1.0);
    arc.phi_hi = arc.phi_lo + rng.uniform(0.1, 4.0);
    arc.phi_periodic = false;
    shapes.emplace_back(arc);
    shapes.emplace_back(rotation::OneAngle(um, uf, rng.uniform(0.0, kPi)));
    const double lo = rng.uniform(0.0, 2.5);
    shapes.emplace_back(rotation::OneAngleRange(um, uf, lo, lo + rng.uniform(0.05, 0.6)));
    shapes.emplace_back(rotation::Free{});
    shapes.emplace_back(rotation::Fixed(rng.pose().linear()));
  }
  int checked = 0;
  for (const RotationPart& r : shapes) {
    ASSERT_TRUE(r.projectsExactly()) << r.name();
    const int n = r.dof();
    auto sample = [&](const double* around, double spread, double* t) {
      for (int i = 0; i < n; ++i) {
        const Parameter p = r.parameter(i);
        const double lo = around ? around[i] - spread : p.min,
                     hi = around ? around[i] + spread : p.max;
        t[i] = rng.uniform(lo, hi);
        if (!p.periodic) t[i] = std::clamp(t[i], p.min, p.max);
      }
    };
    for (int k = 0; k < 6; ++k) {
      double t[3] = {0, 0, 0}, proj[3] = {0, 0, 0};
      sample(nullptr, 0.0, t);
      const Matrix3d target =
          k % 2 == 0 ? Matrix3d(rng.pose().linear())
                     : Matrix3d(axisAngle(rng.unit(), rng.uniform(1e-6, 0.05)) * r.rotation(t));
      r.project(target, proj);
      const double d = rotationDistance(r.rotation(proj), target);
      for (int j = 0; j < 1500; ++j) {
        sample(j % 2 == 0 ? nullptr : proj, j % 4 == 1 ? 1e-3 : 0.1, t);
        ASSERT_GE(rotationDistance(r.rotation(t), target), d - 1e-9) << r.name();
      }
      ++checked;
    }
  }
  EXPECT_EQ(checked, 12 * 6 * 6);
  // A shape the projection only scans (two angles) does not say so.
  EXPECT_FALSE(RotationPart(rotation::TwoAngle(rotation::OneAngle(rng.unit(), rng.unit(), 1.0),
                                               rng.unit(), rng.unit(), 0.3))
                   .projectsExactly());
}

TEST(RotationPart, NamesAreTheOnesResultsWrite) {
  EXPECT_STREQ(RotationPart().name(), "Free");
  EXPECT_STREQ(
      RotationPart(rotation::OneAngleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.1, 0.2)).name(),
      "OneAngleMinMax");
  EXPECT_STREQ(RotationPart(rotation::TwoAngleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.5, 0.7,
                                                    Vector3d::UnitY(), 1.4, 1.7, 1.0))
                   .name(),
               "TwoAngleMinMax");
}

}  // namespace
}  // namespace relpos::test

#include "evaluator.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

// Two angles where the cone of R u passes through the second fixed direction and cos β = cos σ_m:
// there the second angle holds for every spin about u, a whole circle of rotations that θ(φ)
// alone misses (found by the random triples test on integer geometry).
TEST(TwoAngleRotation, DegenerateSpinCircleIsPartOfTheSolution) {
  // u ⊥ X and v ⊥ Z with u = z, v = x: degenerate whichever constraint carries the spin φ.
  Problem p;
  p.addFixedFeature("X", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("Z", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("u", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("v", Feature::makeLine({0, 0, 0}, {1, 0, 0}));
  p.addConstraint("perpendicular", "X", "u");
  p.addConstraint("perpendicular", "Z", "v");
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  auto pose = [](const Vector3d& axis, double t) {
    Isometry3d X = Isometry3d::Identity();
    X.linear() = Eigen::AngleAxisd(t, axis).toRotationMatrix();
    return X;
  };
  // Every spin about z keeps u = z ⊥ X and v in the xy-plane; every spin about x keeps v = x ⊥ Z
  // and u in the yz-plane.
  for (Vector3d axis : {Vector3d(Vector3d::UnitZ()), Vector3d(Vector3d::UnitX())})
    for (double t : {0.0, 0.4, 1.9, -2.5}) {
      Isometry3d X = pose(axis, t);
      ASSERT_LT(worstViolation(p, X), 1e-12);
      EXPECT_TRUE(someBranchContains(s, X)) << "spin " << t << " about " << axis.transpose() << "\n"
                                            << describeBranches(s);
    }
  std::string where;
  EXPECT_LT(worstSampledViolation(p, s, 300, 5, &where), 1e-9) << where;
}

}  // namespace
}  // namespace relpos::test
