#pragma once
// Elementary motions for the chain manifolds (docs/architecture.md: pose(θ) = A · exp(ξ₁θ₁) ⋯ · B).
#include "relpos/core/geometry.hpp"

namespace relpos::manifolds::detail {

// A frame at point a with its z axis along unit d (x from anyPerpendicular, deterministic).
inline Isometry3d lineFrame(const Vector3d& a, const Vector3d& d) {
  Isometry3d X = Isometry3d::Identity();
  const Vector3d x = anyPerpendicular(d);
  X.linear().col(0) = x;
  X.linear().col(1) = d.cross(x);
  X.linear().col(2) = d;
  X.translation() = a;
  return X;
}

// Rotation by `angle` about coordinate axis `axis` (0 = x, 1 = y, 2 = z).
inline Isometry3d rot(int axis, double angle) {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = axisAngle(Vector3d::Unit(axis), angle);
  return X;
}

// Translation by `length` along coordinate axis `axis`.
inline Isometry3d trans(int axis, double length) {
  Isometry3d X = Isometry3d::Identity();
  X.translation()[axis] = length;
  return X;
}

}  // namespace relpos::manifolds::detail
