// pp0+pp (rules/src/pp0_pp.cpp): P pinned at A = 0, Q = P + (1, 0, 0) at q from B = (0, 0, 1). By
// the law of cosines R(1, 0, 0) makes the angle acos((2 − q²) / 2) with (0, 0, 1): q = √2 keeps Q
// in the plane z = 0 (any turn about z), q = 3 is beyond reach.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pinnedAndDistance(double q) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("B", Feature::makePoint({0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("Q", Feature::makePoint({1, 0, 0}));
  p.addConstraint("coincident", "A", "P").addConstraint("distance", "B", "Q", q);
  return p;
}

TEST(Pp0Pp, ThePinTurnsTheDistanceIntoAnAngle) {
  const Problem p = pinnedAndDistance(std::sqrt(2.0));
  std::string fired;
  const RuleOutput out = applyRule("pp0+pp", p, &fired);
  EXPECT_EQ(fired, "pp0+pp/angle");
  ASSERT_EQ(out.alternatives.size(), 1u);
  for (double t : {0.0, 2.0, -1.0}) {
    const Isometry3d X = poseOf({0, 0, 0}, t, Vector3d::UnitZ());
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  // Q turned up to B: the pin holds, the distance does not.
  const Isometry3d up = poseOf({0, 0, 0}, -std::acos(0.0), Vector3d::UnitY());
  ASSERT_FALSE(satisfiesInputs(p, up));
  EXPECT_FALSE(satisfiesAnAlternative(out, up));
}

TEST(Pp0Pp, ADistanceOutOfReachIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp0+pp", pinnedAndDistance(3.0), &fired);
  EXPECT_EQ(fired, "pp0+pp/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
