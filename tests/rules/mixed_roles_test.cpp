// rules/src/mixed_roles.hpp through its two families pl+lp and pl+planep (pl_lp.cpp,
// pl_planep.cpp; PMF App. IV Tables VIII and IX): the mobile point p on the fixed x axis K while
// the fixed origin q lies on the mobile line l (or plane), p being on l and q on K: the points
// coincide, or l lies along K (K in the plane).
#include <gtest/gtest.h>

#include "rule_kit.hpp"

namespace relpos::test {
namespace {

Problem mixedRoles(bool plane) {
  Problem p;
  p.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("q", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("p", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("l", plane ? Feature::makePlane({0, 0, 0}, {0, 0, 1})
                                   : Feature::makeLine({0, 0, 0}, {1, 0, 0}));
  p.addConstraint("coincident", "K", "p").addConstraint("coincident", "q", "l");
  return p;
}

void expectPointsOrAlong(const std::string& family, bool plane, const std::string& want) {
  const Problem p = mixedRoles(plane);
  std::string fired;
  const RuleOutput out = applyRule(family, p, &fired);
  EXPECT_EQ(fired, want);
  // The points coincide (any turn about them), or l slides along K.
  for (const Isometry3d& X : {poseOf({0, 0, 0}, 1.0, Vector3d(0, 1, 1)), poseOf({3, 0, 0}),
                              poseOf({-2, 0, 0}, 0.7, Vector3d::UnitX())}) {
    ASSERT_TRUE(satisfiesInputs(p, X));
    EXPECT_TRUE(satisfiesAnAlternative(out, X));
  }
  EXPECT_FALSE(satisfiesAnAlternative(out, poseOf({0, 1, 0})));
}

TEST(PlLp, ThePointsCoincideOrTheLinesAlign) {
  expectPointsOrAlong("pl+lp", false, "pl+lp/points-or-lines");
}

TEST(PlPlanep, ThePointsCoincideOrTheLineLiesInThePlane) {
  expectPointsOrAlong("pl+planep", true, "pl+planep/points-or-plane");
}

}  // namespace
}  // namespace relpos::test
