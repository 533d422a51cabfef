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
  // The measured quantity, then its distance outside [lo, hi] (0 inside).
  double x = 0.0;
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      x = (p - q).norm();
      break;
    case FundamentalKind::kPointLine:
      x = (p - q).cross(d).norm();
      break;
    case FundamentalKind::kPointPlane:
      x = (p - q).dot(d);
      break;
    case FundamentalKind::kLineLine: {  // skew distance between R·(p, u) + T and (q, d)
      const Vector3d a = R * f.p + T, u = R * f.u;
      const Vector3d n = u.cross(f.d);
      x = n.norm() < 1e-12 ? (a - f.q).cross(f.d).norm() : std::abs((a - f.q).dot(n)) / n.norm();
      break;
    }
    case FundamentalKind::kAngle: {
      const Vector3d u = R * f.p;
      x = std::atan2(u.cross(f.q).norm(), u.dot(f.q));
      break;
    }
  }
  return x < f.lo ? f.lo - x : (x > f.hi ? x - f.hi : 0.0);
  return 1e9;
}

}  // namespace relpos::test
