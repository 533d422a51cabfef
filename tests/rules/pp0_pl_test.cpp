// pp0+pl (rules/src/pp0_pl.cpp): P pinned at the origin, Q = P + (1, 0, 0) on the line y = 1/2,
// z = 0: Q is one of the line's two points 1 from the origin, (±√3/2, 1/2, 0).
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pinnedAndOnLine(double y) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("K", Feature::makeLine({0, y, 0}, {1, 0, 0}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("Q", Feature::makePoint({1, 0, 0}));
  p.addConstraint("coincident", "A", "P").addConstraint("coincident", "K", "Q");
  return p;
}

TEST(Pp0Pl, ThePinLeavesTwoPointsOfTheLine) {
  const Problem p = pinnedAndOnLine(0.5);
  std::string fired;
  const RuleOutput out = applyRule("pp0+pl", p, &fired);
  EXPECT_EQ(fired, "pp0+pl/points");
  ASSERT_EQ(out.alternatives.size(), 2u);
  const double kPi = std::acos(-1.0);
  for (double turn : {kPi / 6, 5 * kPi / 6}) {
    const Isometry3d X = poseOf({0, 0, 0}, turn, Vector3d::UnitZ());
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 0, 0}, kPi / 4, Vector3d::UnitZ())));
}

TEST(Pp0Pl, ALineOutOfReachIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp0+pl", pinnedAndOnLine(3.0), &fired);
  EXPECT_EQ(fired, "pp0+pl/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
