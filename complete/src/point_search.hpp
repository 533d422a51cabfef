#pragma once
// Finding poses of a set of poses (the numeric stage's start for a chart, chart.hpp): a damped
// Gauss–Newton (Levenberg–Marquardt) descent from a start pose on the equations' residuals and
// the inequalities' excess over their inner part (each range shrunk towards its middle), so that
// the pose found lies inside every range, not on its edge, where no chart could be grown.
#include "pose_conditions.hpp"

namespace relpos::complete::detail {

// From (R, t) (normalised, in place): true when the equations hold to 1e-12 — or to the
// slack given, lengths and angles apart: a far-placed problem's rounding may leave equations
// that say one thing twice a little apart, no pose meeting both to 1e-12 — and every inequality
// strictly.
struct EquationSlack {
  double length = 1e-12;  // normalised units (a squared distance: its square root's)
  double angle = 1e-12;
};
bool findPoint(const ConditionSystem& system, Matrix3d* R, Vector3d* t,
               const EquationSlack& slack = EquationSlack());

}  // namespace relpos::complete::detail
