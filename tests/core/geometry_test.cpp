#include "relpos/core/geometry.hpp"

#include <gtest/gtest.h>

#include "random_problems.hpp"

namespace relpos::test {
namespace {

TEST(Geometry, RotationPairsMapsFirstVectorAndPlane) {
  Rng rng(5);
  for (int i = 0; i < 200; ++i) {
    Vector3d u = rng.unit(), v = rng.unit(), r = rng.unit(), s = rng.unit();
    Matrix3d R = rotationPairs(u, v, r, s);
    EXPECT_NEAR((R * R.transpose() - Matrix3d::Identity()).norm(), 0, 1e-12);
    EXPECT_NEAR(R.determinant(), 1, 1e-12);
    EXPECT_TRUE((R * u).isApprox(r, 1e-12));
    EXPECT_NEAR((R * v).dot(r.cross(s)), 0, 1e-12);  // v lands in the plane of r and s
  }
}

TEST(Geometry, RotationBetweenHandlesOppositeVectors) {
  Vector3d u(0, 0, 1);
  EXPECT_TRUE((rotationBetween(u, -u) * u).isApprox(-u, 1e-15));
  EXPECT_TRUE((rotationBetween(u, u) * u).isApprox(u, 1e-15));
}

TEST(Geometry, ClosestPointsOfSkewLines) {
  Vector3d f1, f2;
  ASSERT_TRUE(closestPointsOfLines(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, 2),
                                   Vector3d(0, 1, 0), 1e-12, &f1, &f2));
  EXPECT_TRUE(f1.isApprox(Vector3d(0, 0, 0)));
  EXPECT_TRUE(f2.isApprox(Vector3d(0, 0, 2)));
}

// Lines that meet at X at a tiny angle: their distance is 0 to the coordinates' rounding, and the
// feet sit at X to the crossing's own conditioning (ulp / angle along the lines). Computed from
// d1 × d2 directly, the distance came out ~ulp / angle² (1e-8 … 1e-2 here): two lines that meet
// were "lines that do not meet".
TEST(Geometry, ClosestPointsOfNearlyParallelLinesThatMeet) {
  const Vector3d X(0.3, -0.2, 0.7);
  const Vector3d d1 = Vector3d(1, 2, 3).normalized();
  const Vector3d axis = d1.cross(Vector3d(0.2, -1, 0.4)).normalized();
  for (double angle : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
    for (double sign : {1.0, -1.0}) {
      const Vector3d d2 = sign * (Eigen::AngleAxisd(angle, axis) * d1);
      const Vector3d a1 = X - 0.8 * d1, a2 = X + 0.5 * d2;
      Vector3d f1, f2;
      ASSERT_TRUE(closestPointsOfLines(a1, d1, a2, d2, 1e-11, &f1, &f2)) << angle;
      EXPECT_LT((f2 - f1).norm(), 1e-15) << "angle " << angle;
      EXPECT_LT((f1 - X).norm(), 1e-14 / angle) << "angle " << angle;
      EXPECT_LT((f1 - f2).dot(d1), 1e-15) << "the feet differ across the lines only";
    }
  }
}

// a·b − c·d to about an ulp of the result however much it cancels (Kahan's algorithm with fused
// multiply-adds): the reference for the cross product of the doubles actually given.
double differenceOfProducts(double a, double b, double c, double d) {
  const double w = c * d;
  return std::fma(a, b, -w) - std::fma(c, d, -w);
}

Vector3d referenceCross(const Vector3d& u, const Vector3d& v) {
  return Vector3d(differenceOfProducts(u.y(), v.z(), u.z(), v.y()),
                  differenceOfProducts(u.z(), v.x(), u.x(), v.z()),
                  differenceOfProducts(u.x(), v.y(), u.y(), v.x()));
}

TEST(Geometry, AccurateCrossOfNearlyParallelVectors) {
  const Vector3d u = Vector3d(0.6, -0.3, 0.74).normalized();
  const Vector3d axis = u.cross(Vector3d::UnitX()).normalized();
  for (double angle : {1e-5, 1e-8, 1e-11, 1e-14}) {
    const Vector3d v = Eigen::AngleAxisd(angle, axis) * u;
    const Vector3d exact = referenceCross(u, v);
    // The plain cross product keeps ~1e-16 absolute, i.e. 1e-16 / angle relative; these keep
    // relative precision (the difference v − u is exact).
    EXPECT_LT((accurateCross(u, v) - exact).norm(), 1e-14 * exact.norm()) << angle;
    EXPECT_LT((accurateCross(u, -v) + exact).norm(), 1e-14 * exact.norm()) << angle;
    EXPECT_NEAR(perpendicularPart(v, u).norm() / exact.norm(), 1.0, 1e-13) << angle;
    EXPECT_LT(perpendicularPart(v, u).dot(u), 1e-15 * exact.norm()) << angle;
  }
}

}  // namespace
}  // namespace relpos::test
