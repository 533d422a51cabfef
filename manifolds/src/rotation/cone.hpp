#pragma once
// The cone of a vector at a fixed angle from a fixed direction (PMF eq. 4): shared by the
// one-parallelism, one-angle and angle-range shapes.
#include "relpos/core/geometry.hpp"

namespace relpos::manifolds::rotation::detail {

// The axis w of the rotation by (angle(u_m, u_f) − α) that takes u_m to a vector at angle α from
// u_f (PMF eq. 4, with w = u_m × u_f or any common perpendicular when they are parallel).
Vector3d coneAxis(const Vector3d& u_m, const Vector3d& u_f);

// That rotation: R0 with angle(R0 u_m, u_f) = α.
Matrix3d coneBase(const Vector3d& u_m, const Vector3d& u_f, double alpha);

}  // namespace relpos::manifolds::rotation::detail
