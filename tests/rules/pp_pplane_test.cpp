// pp+pplane (rules/src/pp_pplane.cpp, PMF App. IV Table V) on pairs whose answer follows from the
// geometry: a point at p from A and on a plane at height h below A lies on the circle of radius
// sqrt(p² − h²) about the plane's normal through A.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

// P on the plane z = 0 and at `p` from A = (0, 0, h).
Problem pointOnPlaneAtDistance(double h, double p) {
  Problem pr;
  pr.addFixedFeature("A", Feature::makePoint({0, 0, h}))
      .addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  pr.addConstraint("distance", "A", "P", p).addConstraint("coincident", "S", "P");
  return pr;
}

TEST(PpPplane, CircleHasThePythagoreanRadius) {
  const Problem p = pointOnPlaneAtDistance(1.0, 2.0);
  std::string fired;
  const RuleOutput out = applyRule("pp+pplane", p, &fired);
  EXPECT_EQ(fired, "pp+pplane/circle");
  ASSERT_EQ(out.verdict, RuleVerdict::kReplace);
  ASSERT_EQ(out.alternatives.size(), 1u);
  // The circle: P at sqrt(3) from the normal through A, and still on the plane.
  const Isometry3d on_circle = poseOf(
      {std::sqrt(3.0) * std::cos(0.7), std::sqrt(3.0) * std::sin(0.7), 0}, 1.1, Vector3d(1, 2, 3));
  ASSERT_TRUE(satisfiesInputs(p, on_circle));
  EXPECT_TRUE(satisfiesAnAlternative(out, on_circle));
  const Isometry3d inside = poseOf({1.0, 0, 0});  // on the plane, sqrt(2) from A
  ASSERT_FALSE(satisfiesInputs(p, inside));
  EXPECT_FALSE(satisfiesAnAlternative(out, inside));
}

TEST(PpPplane, SphereTouchingThePlanePinsThePoint) {
  const Problem p = pointOnPlaneAtDistance(2.0, 2.0);
  std::string fired;
  const RuleOutput out = applyRule("pp+pplane", p, &fired);
  EXPECT_EQ(fired, "pp+pplane/tangent");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const Isometry3d touching = poseOf({0, 0, 0}, 0.4, Vector3d(0, 1, 1));
  ASSERT_TRUE(satisfiesInputs(p, touching));
  EXPECT_TRUE(satisfiesAnAlternative(out, touching));
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0.1, 0, 0})));
}

TEST(PpPplane, PlaneBeyondTheSphereIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp+pplane", pointOnPlaneAtDistance(5.0, 2.0), &fired);
  EXPECT_EQ(fired, "pp+pplane/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

TEST(PpPplane, ACoincidenceIsLeftToThePinnedPointRules) {
  std::string fired;
  const RuleOutput out = applyRule("pp+pplane", pointOnPlaneAtDistance(0.0, 0.0), &fired);
  EXPECT_EQ(out.verdict, RuleVerdict::kNoChange);
  EXPECT_EQ(fired, "");
}

}  // namespace
}  // namespace relpos::test
