// A fixed frame far from its features' world positions: placing a feature given at 10⁶ in a frame
// 10⁶ away puts ~1e-10 of rounding into a world point near the origin, which the placed
// coordinates no longer show. The solver's tolerance must still cover it (centring.hpp,
// placementMagnitude), or a small feasible task reads as inconsistent.
#include <gtest/gtest.h>

#include "random_problems.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

// Two parallel fixed planes 3 cm apart near the world origin, given in a fixed frame 10⁶ away,
// and a mobile plane at an exact distance from each (the known pose puts it there): feasible.
TEST(FarFixedFrame, SmallTaskStaysFeasible) {
  Rng rng(2026);
  for (int k = 0; k < 40; ++k) {
    const Isometry3d X_WF = Isometry3d(rng.pose().linear()) * [&] {
      Isometry3d t = Isometry3d::Identity();
      t.translation() = 1e6 * rng.unit();
      return t;
    }();
    const Vector3d n_W = rng.unit();
    const Vector3d w0 = 0.05 * rng.point(), w1 = w0 + 0.03 * n_W + 0.02 * rng.perpendicular(n_W);
    const double v0 = 0.04, v1 = v0 - 0.03;  // the mobile plane is v0 above plane 0, v1 above 1
    const Isometry3d X_WM = rng.pose();
    const Isometry3d X_FW = X_WF.inverse();
    Problem p;
    p.fixed.pose = X_WF;
    p.addFixedFeature("f0", Feature::makePlane(X_FW * w0, X_FW.linear() * n_W));
    p.addFixedFeature("f1", Feature::makePlane(X_FW * w1, X_FW.linear() * n_W));
    const Isometry3d X_MW = X_WM.inverse();
    p.addMobileFeature("m", Feature::makePlane(X_MW * (w0 + v0 * n_W), X_MW.linear() * n_W));
    p.addConstraint("distance", "f0", "m", v0);
    p.addConstraint("distance", "f1", "m", v1);
    const Solution s = solve(p, builtinRegistry());
    ASSERT_EQ(s.status, Status::kSolved) << "case " << k << ": " << s.message;
    EXPECT_TRUE(someBranchContains(s, X_WM)) << "case " << k << "\n" << describeBranches(s);
  }
}

// 1e15 from the origin, coordinates carry ~0.1 of rounding: a task 0.1 across cannot be decided
// there (perpendicular planes would pass for parallel ones). Unhandled, not a wrong `solved`.
TEST(FarFixedFrame, BeyondWhatRoundingCanDecideIsUnhandled) {
  Problem p;
  p.fixed.pose.translation() = Vector3d(0, 0, 1e15);
  p.addFixedFeature("bottom", Feature::makePlane(Vector3d::Zero(), Vector3d::UnitZ()));
  p.addFixedFeature("front", Feature::makePlane(Vector3d::Zero(), Vector3d::UnitY()));
  p.addMobileFeature("palm", Feature::makePlane(Vector3d::Zero(), Vector3d::UnitZ()));
  p.addConstraint("distance", "bottom", "palm", 0.05);
  p.addConstraint("distance", "front", "palm", 0.1);
  const Solution s = solve(p, builtinRegistry());
  EXPECT_EQ(s.status, Status::kUnhandled) << describeBranches(s);
  EXPECT_NE(s.message.find("rounding"), std::string::npos) << s.message;
}

// An initial pose beyond 1e100: its nearest poses' distances would overflow to infinity.
TEST(FarInitialPose, BeyondRangeIsUnhandled) {
  Problem p;
  p.mobile.pose.translation() = Vector3d(1e300, 0, 0);
  p.addFixedFeature("O", Feature::makePoint(Vector3d::Zero()));
  p.addMobileFeature("o", Feature::makePoint(Vector3d::Zero()));
  p.addConstraint("coincident", "O", "o");
  const Solution s = solve(p, builtinRegistry());
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_NE(s.message.find("initial pose"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace relpos::test
