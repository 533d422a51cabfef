// range:pplane+pplane (rules/src/range_pplane_pplane.cpp, Somani 004 Table VII): one point
// between z = 0 and z = 2 and within a signed range of a parallel plane at z = 1 (its normal
// either way) is between their overlap's planes.
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem twoSlabs(const Vector3d& n2, double lo2, double hi2) {
  Problem p;
  p.addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("T", Feature::makePlane({0, 0, 1}, n2))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "S", "P", 1.0).addConstraint("distance", "T", "P", 1.0);
  makeRange(p, 0, 0.0, 2.0);
  makeRange(p, 1, lo2, hi2);
  return p;
}

TEST(RangePplanePplane, SlabsFacingEitherWayLeaveTheirOverlap) {
  // T's normal points down: −2 ≤ (1 − z) ≤ 0 is 1 ≤ z ≤ 3; with 0 ≤ z ≤ 2, 1 ≤ z ≤ 2.
  const Problem p = twoSlabs({0, 0, -1}, -2.0, 0.0);
  std::string fired;
  const RuleOutput out = applyRule("range:pplane+pplane", p, &fired);
  EXPECT_EQ(fired, "range:pplane+pplane/overlap");
  ASSERT_EQ(out.alternatives.size(), 1u);
  for (double z : {1.0, 1.5, 2.0}) {
    const Isometry3d X = poseOf({4, -1, z}, z);
    ASSERT_TRUE(satisfiesInputs(p, X)) << z;
    EXPECT_TRUE(satisfiesAnAlternative(out, X)) << z;
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 0, 0.5})));
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 0, 2.5})));
}

TEST(RangePplanePplane, ASlabInsideTheOtherMakesTheWiderRedundant) {
  std::string fired;  // 0.5 ≤ z ≤ 1.5 inside 0 ≤ z ≤ 2
  const RuleOutput out = applyRule("range:pplane+pplane", twoSlabs({0, 0, 1}, -0.5, 0.5), &fired);
  EXPECT_EQ(fired, "range:pplane+pplane/nested");
  EXPECT_EQ(out.verdict, RuleVerdict::kRedundantFirst);
}

TEST(RangePplanePplane, SlabsApartAreIncompatible) {
  std::string fired;  // 3 ≤ z ≤ 4 against 0 ≤ z ≤ 2
  const RuleOutput out = applyRule("range:pplane+pplane", twoSlabs({0, 0, 1}, 2.0, 3.0), &fired);
  EXPECT_EQ(fired, "range:pplane+pplane/disjoint");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
