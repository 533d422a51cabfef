// pl+pl (rules/src/pl_pl.cpp, PMF App. IV Tables III and IV) for one point on two lines: crossing
// lines pin it where they cross, one line twice is redundant, distinct parallel lines cannot both
// hold it.
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem pointOnTwoLines(const Vector3d& c2, const Vector3d& d2) {
  Problem p;
  p.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("L", Feature::makeLine(c2, d2))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("coincident", "K", "P").addConstraint("coincident", "L", "P");
  return p;
}

TEST(PlPl, CrossingLinesPinThePointWhereTheyCross) {
  const Problem p = pointOnTwoLines({3, 1, 0}, {0, 1, 0});  // x = 3 in the plane z = 0
  std::string fired;
  const RuleOutput out = applyRule("pl+pl", p, &fired);
  EXPECT_EQ(fired, "pl+pl/lines-meet");
  ASSERT_EQ(out.alternatives.size(), 1u);
  const Isometry3d X = poseOf({3, 0, 0}, 1.3, Vector3d(1, 1, 1));
  ASSERT_TRUE(satisfiesInputs(p, X));
  EXPECT_TRUE(satisfiesAnAlternative(out, X));
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({2, 0, 0})));
}

TEST(PlPl, OneLineTwiceIsRedundant) {
  std::string fired;
  const RuleOutput out = applyRule("pl+pl", pointOnTwoLines({-4, 0, 0}, {-1, 0, 0}), &fired);
  EXPECT_EQ(fired, "pl+pl/same-line");
  EXPECT_EQ(out.verdict, RuleVerdict::kRedundantSecond);
}

TEST(PlPl, DistinctParallelLinesAreIncompatible) {
  std::string fired;
  const RuleOutput out = applyRule("pl+pl", pointOnTwoLines({0, 1, 0}, {1, 0, 0}), &fired);
  EXPECT_EQ(fired, "pl+pl/incompatible");
  EXPECT_EQ(out.verdict, RuleVerdict::kIncompatible);
}

}  // namespace
}  // namespace relpos::test
