// A branch as MoveIt goal constraints (relpos/report/moveit.hpp), from its TSR chain: one link of
// slides and at most one turn is exactly a box for the point of the mobile object on the turn's
// axis times a tolerance about one of its axes, when the turn's axis is one of them.
#include <algorithm>
#include <cmath>

#include "relpos/report/moveit.hpp"
#include "relpos/report/tsr.hpp"

namespace relpos {
namespace {

// The tolerance of an angle that does not vary: MoveIt refuses a pose beyond a tolerance, and a
// rotation computed in doubles is that far off.
constexpr double kFixedAngle = 1e-9;

// The goal that admits one pose only: conservative for any branch.
MoveItGoal onePose(const Isometry3d& X, double thin, std::string why) {
  MoveItGoal g;
  g.why = std::move(why);
  g.box_pose.translation() = X.translation();
  g.box_dimensions = Vector3d::Constant(thin);
  g.orientation = Eigen::Quaterniond(X.linear());
  g.axis_tolerances = Vector3d::Constant(kFixedAngle);
  return g;
}

}  // namespace

MoveItGoal moveitGoalOf(const Problem& problem, const Branch& branch, const Params& at,
                        double window) {
  const Isometry3d X_at = branch.manifold->pose(at);
  const double thin = 1e-9 * std::max({1.0, problem.lengthScale(), X_at.translation().norm()});
  if (!branch.exact)
    return onePose(X_at, thin, "a numeric branch: its nearest pose only");
  const TsrExport tsr = tsrChainOf(problem, branch, at, window);
  if (!tsr.exact) return onePose(X_at, thin, "no TSR chain (" + tsr.why + "): its nearest pose only");
  if (tsr.chain.size() != 1)
    return onePose(X_at, thin,
                   "a chain of " + std::to_string(tsr.chain.size()) +
                       " TSRs, which MoveIt's position-times-orientation constraints cannot "
                       "hold: its nearest pose only");
  const TsrLink& link = tsr.chain[0];
  MoveItGoal g;
  g.windowed = tsr.windowed;
  // The mobile point at the link frame's origin (on the turn's axis): its position is
  // T0_w·(x, y, z) whatever the turn, so the box holds it exactly.
  g.target_point_offset = link.Tw_e.inverse().translation();
  Vector3d mid, size;
  for (int k = 0; k < 3; ++k) {
    mid[k] = 0.5 * (link.Bw[k][0] + link.Bw[k][1]);
    size[k] = std::max(link.Bw[k][1] - link.Bw[k][0], thin);
  }
  g.box_pose.linear() = link.T0_w.linear();
  g.box_pose.translation() = link.T0_w * mid;
  g.box_dimensions = size;
  // Orientations R_F·Rz(yaw)·R_E: against the middle one the error is a turn by yaw − mid about
  // R_Eᵀ·z, the link frame's z in the mobile object's frame.
  const double yaw_mid = 0.5 * (link.Bw[5][0] + link.Bw[5][1]);
  const double half = 0.5 * (link.Bw[5][1] - link.Bw[5][0]);
  const Matrix3d R_mid = link.T0_w.linear() * Eigen::AngleAxisd(yaw_mid, Vector3d::UnitZ()) *
                         link.Tw_e.linear();
  g.orientation = Eigen::Quaterniond(R_mid);
  g.axis_tolerances = Vector3d::Constant(kFixedAngle);
  g.exact = true;
  if (half > 0.0) {
    const Vector3d axis = link.Tw_e.linear().transpose() * Vector3d::UnitZ();
    int k = 0;
    axis.cwiseAbs().maxCoeff(&k);
    if (std::abs(std::abs(axis[k]) - 1.0) > 1e-12) {
      g.exact = false;
      g.why = "the turn is about no axis of the mobile object: its middle orientation only";
    } else {
      g.axis_tolerances[k] = std::min(half, kPi);
    }
  }
  return g;
}

}  // namespace relpos
