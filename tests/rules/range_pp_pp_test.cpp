// range:pp+pp (rules/src/range_pp_pp.cpp, Somani 004 Table VII): two distance ranges between the
// same two points are one range on their overlap, the narrower when nested, nothing when apart.
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem twoRanges(double lo1, double hi1, double lo2, double hi2) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "A", "P", 1.0).addConstraint("distance", "A", "P", 1.0);
  makeRange(p, 0, lo1, hi1);
  makeRange(p, 1, lo2, hi2);
  return p;
}

TEST(RangePpPp, OverlappingRangesLeaveTheOverlap) {
  const Problem p = twoRanges(1, 3, 2, 4);
  std::string fired;
  const RuleOutput out = applyRule("range:pp+pp", p, &fired);
  EXPECT_EQ(fired, "range:pp+pp/overlap");
  ASSERT_EQ(out.alternatives.size(), 1u);
  for (double r : {2.0, 2.5, 3.0}) {
    const Isometry3d X = poseOf({0, r, 0}, r);
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 1.5, 0})));  // in the first range only
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 3.5, 0})));  // in the second only
}

TEST(RangePpPp, TheWiderOfNestedRangesIsRedundant) {
  std::string fired;
  const RuleOutput out = applyRule("range:pp+pp", twoRanges(1, 4, 2, 3), &fired);
  EXPECT_EQ(fired, "range:pp+pp/nested");
  EXPECT_EQ(out.verdict, RuleVerdict::kRedundantFirst);
}

TEST(RangePpPp, RangesApartAreIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("range:pp+pp", twoRanges(1, 2, 3, 4), &fired);
  EXPECT_EQ(fired, "range:pp+pp/disjoint");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
