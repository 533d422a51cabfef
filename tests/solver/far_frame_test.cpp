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

}  // namespace
}  // namespace relpos::test
