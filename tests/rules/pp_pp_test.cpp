// pp+pp (rules/src/pp_pp.cpp, PMF App. IV Table I) for one mobile point at distances from A and
// B = A + (2, 0, 0): two spheres of radius √2 meet in the unit circle in the plane x = 1, spheres
// of radius 1 touch at (1, 0, 0), spheres of radius 1/2 do not meet.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pointAtTwoDistances(double p, double q) {
  Problem pr;
  pr.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("B", Feature::makePoint({2, 0, 0}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  pr.addConstraint("distance", "A", "P", p).addConstraint("distance", "B", "P", q);
  return pr;
}

TEST(PpPp, TwoSpheresMeetInACircle) {
  const Problem p = pointAtTwoDistances(std::sqrt(2.0), std::sqrt(2.0));
  std::string fired;
  const RuleOutput out = applyRule("pp+pp", p, &fired);
  EXPECT_EQ(fired, "pp+pp/circle");
  ASSERT_EQ(out.alternatives.size(), 1u);
  for (double t : {0.0, 1.0, 4.0}) {
    const Isometry3d X = poseOf({1, std::cos(t), std::sin(t)}, t, Vector3d(1, 0, 2));
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({1, 0.5, 0})));
}

TEST(PpPp, TouchingSpheresPinThePoint) {
  const Problem p = pointAtTwoDistances(1.0, 1.0);
  std::string fired;
  const RuleOutput out = applyRule("pp+pp", p, &fired);
  EXPECT_EQ(fired, "pp+pp/tangent-spheres");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const Isometry3d X = poseOf({1, 0, 0}, 2.0);
  ASSERT_TRUE(satisfiesInputs(p, X));
  EXPECT_TRUE(satisfiesAnAlternative(out, X));
}

TEST(PpPp, SpheresTooSmallToMeetAreIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp+pp", pointAtTwoDistances(0.5, 0.5), &fired);
  EXPECT_EQ(fired, "pp+pp/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
