#pragma once
// A translational constraint's own measure at a pose (R, T), computed from its definition
// (docs/spec.md §1: a point of one side against the element (q, d) of the other, the mobile side's
// geometry moved by the pose), independently of the manifolds' shapeOf.
#include <cmath>

#include "relpos/core/fundamental.hpp"

namespace relpos::test {

inline double measure(const Fundamental& f, const Matrix3d& R, const Vector3d& T) {
  const bool mobile_point = f.point_side == Side::kMobile;
  const Vector3d p = mobile_point ? Vector3d(R * f.p + T) : f.p;
  const Vector3d q = mobile_point ? f.q : Vector3d(R * f.q + T);
  const Vector3d d = mobile_point ? f.d : Vector3d(R * f.d);
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      return (p - q).norm();
    case FundamentalKind::kPointLine:
      return (p - q).cross(d).norm();
    case FundamentalKind::kPointPlane:
      return (p - q).dot(d);
    default:
      return NAN;
  }
}

// How far f is from holding at (R, T): 0 inside its range.
inline double violation(const Fundamental& f, const Matrix3d& R, const Vector3d& T) {
  const double m = measure(f, R, T);
  return m < f.lo ? f.lo - m : (m > f.hi ? m - f.hi : 0.0);
}

}  // namespace relpos::test
