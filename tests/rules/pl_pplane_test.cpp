// pl+pplane (rules/src/pl_pplane.cpp, PMF App. IV Table VI) for one point on a line and a plane,
// or at a distance from a line parallel to the plane.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pointAtLineAndOnPlane(const Vector3d& c, const Vector3d& d, double p) {
  Problem pr;
  pr.addFixedFeature("K", Feature::makeLine(c, d))
      .addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  pr.addConstraint("distance", "K", "P", p).addConstraint("coincident", "S", "P");
  return pr;
}

TEST(PlPplane, ALineCrossingThePlanePinsThePoint) {
  const Problem p = pointAtLineAndOnPlane({0, 0, 1}, Vector3d(1, 0, 1).normalized(), 0.0);
  std::string fired;
  const RuleOutput out = applyRule("pl+pplane", p, &fired);
  EXPECT_EQ(fired, "pl+pplane/line-meets-plane");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const Isometry3d X = poseOf({-1, 0, 0}, 0.8);  // (0, 0, 1) − (1, 0, 1)
  ASSERT_TRUE(satisfiesInputs(p, X));
  EXPECT_TRUE(satisfiesAnAlternative(out, X));
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({1, 0, 0})));
}

TEST(PlPplane, ALineInThePlaneMakesThePlaneRedundant) {
  std::string fired;
  const RuleOutput out =
      applyRule("pl+pplane", pointAtLineAndOnPlane({2, 3, 0}, {1, 0, 0}, 0.0), &fired);
  EXPECT_EQ(fired, "pl+pplane/implied");
  EXPECT_EQ(out.verdict, RuleVerdict::kRedundantSecond);
}

TEST(PlPplane, ACylinderAboveThePlaneCutsTwoLines) {
  // Radius 2 about a line 1 above the plane: the lines y = ±√3 of the plane.
  const Problem p = pointAtLineAndOnPlane({0, 0, 1}, {1, 0, 0}, 2.0);
  std::string fired;
  const RuleOutput out = applyRule("pl+pplane", p, &fired);
  EXPECT_EQ(fired, "pl+pplane/lines-on-plane");
  ASSERT_EQ(out.alternatives.size(), 2u);
  for (double y : {std::sqrt(3.0), -std::sqrt(3.0)}) {
    const Isometry3d X = poseOf({5, y, 0}, y);
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({5, 1, 0})));
}

TEST(PlPplane, ALineParallelAboveThePlaneCannotHoldItsPoint) {
  std::string fired;
  const RuleOutput out =
      applyRule("pl+pplane", pointAtLineAndOnPlane({0, 0, 1}, {1, 0, 0}, 0.0), &fired);
  EXPECT_EQ(fired, "pl+pplane/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
