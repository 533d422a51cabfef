#pragma once
// Isolated poses where two constraints touch (docs/spec.md §8.7): a grid task's sphere of
// points at a distance tangent to the plane a feature slides on, a cylinder touching a line —
// the constraints meet at a pose where their equations are dependent (no chart there, no
// Krawczyk test), the solutions a double root. Such a pose is an isolated critical point of
// one equation g on the set of the others h: h = 0 and ∇g = Σ λ ∇h, a square system regular
// there, which Krawczyk's test proves (a unique critical point in a box); g at it is then
// proven within half its tolerance. Only where g's Hessian on the set of the others is
// definite — an extremum, the only pose of the set near it; at a saddle the set crosses there
// and is not isolated.
#include "pose_conditions.hpp"

namespace relpos::complete::detail {

struct TangentPose {
  Matrix3d R = Matrix3d::Identity();  // normalised
  Vector3d t = Vector3d::Zero();
  double radius = 0.0;  // the proven box's half-width in the local coordinates about it
};

// From a pose (R0, t0) of the system where its equations are dependent, one of them dependent
// on the others: the touching pose near it, proven; false otherwise (rank not short by one,
// no critical point proven, a saddle, or over the proven box an equation not within half its
// tolerance, an implied one — dropped from the system as following from others, in its frame —
// not within its tolerance, an inequality not within its range). length_tol, angle_tol: the
// tolerance, normalised.
bool tangentPose(const ConditionSystem& system, const std::vector<Condition>& implied,
                 const Matrix3d& R0, const Vector3d& t0, double length_tol, double angle_tol,
                 TangentPose* out);

}  // namespace relpos::complete::detail
