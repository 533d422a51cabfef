#pragma once
// Residual of a fundamental constraint at pose (R, T), written from PMF §III directly (not from
// the solver's shapes), for rule property tests.
#include <cmath>

#include "relpos/core/fundamental.hpp"

namespace relpos::test {

inline double fundamentalResidual(const Fundamental& f, const Isometry3d& X) {
  const Matrix3d R = X.linear();
  const Vector3d T = X.translation();
  const bool pm = f.point_side == Side::kMobile;
  const Vector3d p = pm ? Vector3d(R * f.p + T) : f.p;  // the point, in world
  const Vector3d q = pm ? f.q : Vector3d(R * f.q + T);  // the other element's point
  const Vector3d d = pm ? f.d : Vector3d(R * f.d);      // its direction / normal
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      return std::abs((p - q).norm() - f.value());
    case FundamentalKind::kPointLine:
      return std::abs((p - q).cross(d).norm() - f.value());
    case FundamentalKind::kPointPlane:
      return std::abs((p - q).dot(d) - f.value());
    case FundamentalKind::kLineLine: {  // skew distance between R·(p, u) + T and (q, d)
      const Vector3d a = R * f.p + T, u = R * f.u;
      const Vector3d n = u.cross(f.d);
      const double dist =
          n.norm() < 1e-12 ? (a - f.q).cross(f.d).norm() : std::abs((a - f.q).dot(n)) / n.norm();
      return dist < f.lo ? f.lo - dist : (dist > f.hi ? dist - f.hi : 0.0);
    }
    case FundamentalKind::kAngle: {
      const Vector3d u = R * f.p;
      return std::abs(std::atan2(u.cross(f.q).norm(), u.dot(f.q)) - f.value());
    }
  }
  return 1e9;
}

}  // namespace relpos::test
