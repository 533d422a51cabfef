// range:pl+pl (rules/src/range_pl_pl.cpp, Somani 004 Table VII): two distance ranges of one point
// from the same axis (given by two of its points) are one range on their overlap.
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem twoRangesFromOneAxis(double lo1, double hi1, double lo2, double hi2) {
  Problem p;
  p.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("K2", Feature::makeLine({5, 0, 0}, {-1, 0, 0}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "K", "P", 1.0).addConstraint("distance", "K2", "P", 1.0);
  makeRange(p, 0, lo1, hi1);
  makeRange(p, 1, lo2, hi2);
  return p;
}

TEST(RangePlPl, CoaxialRangesLeaveTheOverlap) {
  const Problem p = twoRangesFromOneAxis(1, 3, 2, 4);
  std::string fired;
  const RuleOutput out = applyRule("range:pl+pl", p, &fired);
  EXPECT_EQ(fired, "range:pl+pl/overlap");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const Isometry3d X = poseOf({7, 0, 2.5}, 0.5);
  ASSERT_TRUE(satisfiesInputs(p, X));
  EXPECT_TRUE(satisfiesAnAlternative(out, X));
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({-2, 1.5, 0})));
}

TEST(RangePlPl, RangesApartAreIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("range:pl+pl", twoRangesFromOneAxis(1, 2, 3, 4), &fired);
  EXPECT_EQ(fired, "range:pl+pl/disjoint");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
