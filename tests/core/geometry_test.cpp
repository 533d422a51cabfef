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

}  // namespace
}  // namespace relpos::test
