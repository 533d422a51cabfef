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

// One point 3 from the z axis and 2 from a parallel axis 1 + 3e-7 away: the cylinders barely
// cross, at (k1, ±k2) with k2 = 1.9e-3. With the axes' distance and the radii each known only to
// the tolerance (1.2e-8, a problem placed 1e6 from its origin), the crossings move by 1e-4: each
// line the rule gives must carry that (it said exact, and a point on such a line and on another
// through the true crossing was then found on lines that do not meet).
TEST(PlPl, NearlyTangentCylindersCarryWhereTheirCrossingsMayBe) {
  const double db = 1.0 + 3e-7, p = 3.0, q = 2.0;
  Tolerance tol;
  tol.length = 1.2e-8;
  const Fundamental a = Fundamental::pointLine(Side::kMobile, Vector3d::Zero(), Vector3d::Zero(),
                                               Vector3d::UnitZ(), p, 1);
  const Fundamental b = Fundamental::pointLine(Side::kMobile, Vector3d::Zero(), Vector3d(db, 0, 0),
                                               Vector3d::UnitZ(), q, 2);
  std::string fired;
  const RuleOutput out = applyRule("pl+pl", {a, b}, &fired, tol);
  ASSERT_EQ(fired, "pl+pl/parallel-cylinders");
  ASSERT_EQ(out.alternatives.size(), 2u);
  // The crossings of the cylinders the inputs may stand for (each off by the tolerance).
  for (double sd : {-1.0, 1.0})
    for (double sp : {-1.0, 1.0})
      for (double sq : {-1.0, 1.0}) {
        const long double D = db + sd * tol.length, P = p + sp * tol.length,
                          Q = q + sq * tol.length;
        const long double k1 = (D * D + P * P - Q * Q) / (2 * D);
        const long double k2 = std::sqrt(std::max<long double>(P * P - k1 * k1, 0));
        for (double side : {-1.0, 1.0}) {
          const Vector3d x(static_cast<double>(k1), static_cast<double>(side * k2), 0.0);
          double nearest = 1e9;  // from the crossing to the rule's lines, less their uncertainty
          for (const auto& alt : out.alternatives)
            for (const Fundamental& f : alt) {
              const Vector3d off = x - f.q;
              const double d = (off - off.dot(f.d) * f.d).norm();
              nearest = std::min(nearest, d - f.value() - f.err);
            }
          EXPECT_LE(nearest, 1e-12) << sd << sp << sq << side;
        }
      }
}

}  // namespace
}  // namespace relpos::test
