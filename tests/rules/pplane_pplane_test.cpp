// pplane+pplane (rules/src/pplane_pplane.cpp, PMF App. IV Table VII, Fig. 3) on one point and two
// planes: crossing planes put it on their common line, one plane twice is redundant, two distinct
// parallel planes cannot both hold it.
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pointOnTwoPlanes(const Vector3d& c2, const Vector3d& n2) {
  Problem p;
  p.addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("T", Feature::makePlane(c2, n2))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("coincident", "S", "P").addConstraint("coincident", "T", "P");
  return p;
}

TEST(PplanePplane, CrossingPlanesPutThePointOnTheirLine) {
  const Problem p = pointOnTwoPlanes({1, 0, 0}, {1, 0, 0});  // z = 0 and x = 1: the line x=1, z=0
  std::string fired;
  const RuleOutput out = applyRule("pplane+pplane", p, &fired);
  EXPECT_EQ(fired, "pplane+pplane/planes-meet");
  ASSERT_EQ(out.alternatives.size(), 1u);
  ASSERT_EQ(out.alternatives[0].size(), 1u);
  for (double y : {-3.0, 0.0, 2.5}) {
    const Isometry3d X = poseOf({1, y, 0}, 0.3 * y, Vector3d(1, 1, 0));
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({1, 0, 0.5})));
}

TEST(PplanePplane, PlanesParallelWithinTheToleranceYetApartMeetFarAway) {
  // 1 apart here, tilted by 1e-10 rad (parallel within the 1e-9 angle tolerance, beyond the
  // inputs' rounding): they still meet, along y, 1e10 away.
  const Problem p = pointOnTwoPlanes({0, 0, 1}, Vector3d(1e-10, 0, 1).normalized());
  std::string fired;
  const RuleOutput out = applyRule("pplane+pplane", p, &fired);
  EXPECT_EQ(fired, "pplane+pplane/planes-meet");
  ASSERT_EQ(out.alternatives.size(), 1u);
  ASSERT_EQ(out.alternatives[0].size(), 1u);
  const Fundamental& line = out.alternatives[0][0];
  EXPECT_EQ(line.kind, FundamentalKind::kPointLine);
  EXPECT_NEAR(std::abs(line.d.dot(Vector3d::UnitY())), 1.0, 1e-12);
}

TEST(PplanePplane, OnePlaneTwiceIsRedundant) {
  std::string fired;
  const RuleOutput out = applyRule("pplane+pplane", pointOnTwoPlanes({5, 1, 0}, {0, 0, 1}), &fired);
  EXPECT_EQ(fired, "pplane+pplane/same-plane");
  EXPECT_EQ(out.verdict, RuleVerdict::kRedundantSecond);
}

TEST(PplanePplane, DistinctParallelPlanesAreIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pplane+pplane", pointOnTwoPlanes({0, 0, 1}, {0, 0, 1}), &fired);
  EXPECT_EQ(fired, "pplane+pplane/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
