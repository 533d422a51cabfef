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

// Newton's method, least-norm steps, on the equations alone from (R, t) (in place): a pose a
// descent found holds them to its acceptance (1e-12, or the slack of a far-placed problem's
// rounding); a chart's proof about it needs a slice as wide as that residual over the
// equations' conditioning, and what it proves of a dropped equation is no tighter. A few steps
// take the residual to rounding. Stops where a step does not lower the residual (or the
// equations are dependent there); never moves further than 1e-6.
void polishPose(const std::vector<Condition>& equations, Matrix3d* R, Vector3d* t);

}  // namespace relpos::complete::detail
