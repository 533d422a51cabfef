// Rotation parts checked against their defining constraints, independently of the matcher.
#include "relpos/manifolds/rotation_part.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(RotationPart, TwoAngleRotationsMeetBothAngles) {
  Rng rng(5);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const Vector3d um = rng.unit(), uf = rng.unit(), vm = rng.unit(), vf = rng.unit();
    // Angles some rotation makes, so that the set is not empty.
    const Matrix3d R_true = rng.pose().linear();
    const double alpha = angleBetween(R_true * um, uf), beta = angleBetween(R_true * vm, vf);
    for (double sign : {1.0, -1.0}) {
      rotation::TwoAngle two(rotation::OneAngle(um, uf, alpha), vm, vf, std::cos(beta));
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

TEST(RotationPart, FixedIsTheNearestRotationAndHasNoParameters) {
  Rng rng(6);
  const Matrix3d R = rng.pose().linear();
  const RotationPart r = rotation::Fixed(R);
  EXPECT_EQ(r.dof(), 0);
  EXPECT_LT(rotationDistance(r.rotation(nullptr), R), 1e-12);
  EXPECT_LT(rotationDistance(r.baseRotation(), R), 1e-12);
  EXPECT_EQ(r.spinAxis(), nullptr);
}

TEST(RotationPart, NamesAreTheOnesResultsWrite) {
  EXPECT_STREQ(RotationPart().name(), "Free");
  EXPECT_STREQ(
      RotationPart(rotation::OneAngleRange(Vector3d::UnitX(), Vector3d::UnitZ(), 0.1, 0.2)).name(),
      "OneAngleMinMax");
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
