// range:pline+pplane (rules/src/range_pline_pplane.cpp): a point 1 to 2 from the x axis and on a
// plane z = h parallel to it. With s its offset across the axis's trace, 1 ≤ h² + s² ≤ 4: two
// strips √(1 − h²) ≤ |s| ≤ √(4 − h²) for h < 1, one strip |s| ≤ √(4 − h²) for 1 ≤ h ≤ 2, none
// beyond.
#include <gtest/gtest.h>

#include <cmath>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem thickCylinderCutAt(double h) {
  Problem p;
  p.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("S", Feature::makePlane({0, 0, h}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "K", "P", 1.0).addConstraint("coincident", "S", "P");
  makeRange(p, 0, 1.0, 2.0);
  return p;
}

TEST(RangePlinePplane, APlaneThroughTheHoleCutsTwoStrips) {
  const Problem p = thickCylinderCutAt(0.5);
  std::string fired;
  const RuleOutput out = applyRule("range:pline+pplane", p, &fired);
  EXPECT_EQ(fired, "range:pline+pplane/two-strips");
  ASSERT_EQ(out.alternatives.size(), 2u);
  for (double s : {1.5, -1.2, std::sqrt(0.75), -std::sqrt(3.75)}) {
    const Isometry3d X = poseOf({3, s, 0.5}, s);
    ASSERT_TRUE(satisfiesInputs(p, X)) << s;
    EXPECT_TRUE(satisfiesAnAlternative(out, X)) << s;
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({3, 0.5, 0.5})));  // in the hole
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({3, 2.0, 0.5})));  // beyond the wall
}

TEST(RangePlinePplane, APlaneThroughTheWallCutsOneStrip) {
  const Problem p = thickCylinderCutAt(1.5);
  std::string fired;
  const RuleOutput out = applyRule("range:pline+pplane", p, &fired);
  EXPECT_EQ(fired, "range:pline+pplane/one-strip");
  ASSERT_EQ(out.alternatives.size(), 1u);
  for (double s : {0.0, 1.3, -1.0}) {
    const Isometry3d X = poseOf({-1, s, 1.5});
    ASSERT_TRUE(satisfiesInputs(p, X)) << s;
    EXPECT_TRUE(satisfiesAnAlternative(out, X)) << s;
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({-1, 1.4, 1.5})));
}

TEST(RangePlinePplane, APlaneBeyondTheRangeIsIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("range:pline+pplane", thickCylinderCutAt(3.0), &fired);
  EXPECT_EQ(fired, "range:pline+pplane/disjoint");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
