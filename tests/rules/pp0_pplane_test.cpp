// pp0+pplane (rules/src/pp0_pplane.cpp): P pinned at the origin, Q = P + (1, 0, 0) on the plane
// z = h: R(1, 0, 0) is at acos(h) from the plane's normal (60° for h = 1/2), out of reach for
// h > 1.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pinnedAndOnPlane(double h) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("S", Feature::makePlane({0, 0, h}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("Q", Feature::makePoint({1, 0, 0}));
  p.addConstraint("coincident", "A", "P").addConstraint("coincident", "S", "Q");
  return p;
}

TEST(Pp0Pplane, ThePinTurnsThePlaneIntoAnAngle) {
  const Problem p = pinnedAndOnPlane(0.5);
  std::string fired;
  const RuleOutput out = applyRule("pp0+pplane", p, &fired);
  EXPECT_EQ(fired, "pp0+pplane/angle");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const double tilt = std::asin(0.5);  // x tipped up by 30° (about −y), then any turn about z
  for (double t : {0.0, 1.0, -2.5}) {
    Isometry3d X =
        poseOf({0, 0, 0}, t, Vector3d::UnitZ()) * poseOf({0, 0, 0}, -tilt, Vector3d::UnitY());
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 0, 0})));
}

TEST(Pp0Pplane, APlaneOutOfReachIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pp0+pplane", pinnedAndOnPlane(3.0), &fired);
  EXPECT_EQ(fired, "pp0+pplane/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
