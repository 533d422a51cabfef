// pp+pl (rules/src/pp_pl.cpp, PMF App. IV Table II) for one point at p from A and at q from the
// x axis.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pointFromPointAndAxis(const Vector3d& a, double p, double q) {
  Problem pr;
  pr.addFixedFeature("A", Feature::makePoint(a))
      .addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  pr.addConstraint("distance", "A", "P", p).addConstraint("distance", "K", "P", q);
  return pr;
}

TEST(PpPl, ASphereMeetsTheLineInTwoPoints) {
  // On the axis (q = 0) and √2 from A = (0, 1, 0): x = ±1.
  const Problem p = pointFromPointAndAxis({0, 1, 0}, std::sqrt(2.0), 0.0);
  std::string fired;
  const RuleOutput out = applyRule("pp+pl", p, &fired);
  EXPECT_EQ(fired, "pp+pl/sphere-meets-line");
  ASSERT_EQ(out.alternatives.size(), 2u);
  for (double x : {1.0, -1.0}) {
    const Isometry3d X = poseOf({x, 0, 0}, x);
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0.5, 0, 0})));
}

TEST(PpPl, ASphereAboutAPointOfTheAxisMeetsTheCylinderInTwoCircles) {
  // 2 from A = (2, 0, 0) and 1 from the axis: the circles of radius 1 at x = 2 ± √3.
  const Problem p = pointFromPointAndAxis({2, 0, 0}, 2.0, 1.0);
  std::string fired;
  const RuleOutput out = applyRule("pp+pl", p, &fired);
  EXPECT_EQ(fired, "pp+pl/circles-about-axis");
  ASSERT_EQ(out.alternatives.size(), 2u);
  for (double s : {1.0, -1.0})
    for (double t : {0.0, 2.0}) {
      const Isometry3d X = poseOf({2 + s * std::sqrt(3.0), std::cos(t), std::sin(t)}, t);
      ASSERT_TRUE(satisfiesInputs(p, X));
      EXPECT_TRUE(satisfiesAnAlternative(out, X));
    }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({2, 1, 0})));
}

TEST(PpPl, ALineOutOfTheSpheresReachIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp+pl", pointFromPointAndAxis({0, 5, 0}, 1.0, 1.0), &fired);
  EXPECT_EQ(fired, "pp+pl/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
