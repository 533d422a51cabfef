#pragma once
// Helpers shared by the rule families: building results on the same sides as the inputs.
#include <cmath>

#include "relpos/core/rule.hpp"

namespace relpos::rules::detail {

using Alt = FixedVector<Fundamental, kMaxRuleOutputs>;

// d(a's point, X) = 0 where X is a point on the other side of a.
inline Fundamental pinPoint(const Fundamental& a, const Vector3d& x) {
  return a.point_side == Side::kMobile ? Fundamental::pointPoint(a.p, x, 0.0, a.sources)
                                       : Fundamental::pointPoint(x, a.p, 0.0, a.sources);
}
inline Fundamental onLine(const Fundamental& a, const Vector3d& c, const Vector3d& d, double v) {
  return Fundamental::pointLine(a.point_side, a.p, c, d, v, a.sources);
}
inline Fundamental onPlane(const Fundamental& a, const Vector3d& c, const Vector3d& n) {
  return Fundamental::pointPlane(a.point_side, a.p, c, n, 0.0, a.sources);
}
// Angle between a vector of the point side (u_a) and one of the other side (u_b).
inline Fundamental angleAB(Side point_side, const Vector3d& u_a, const Vector3d& u_b, double v) {
  return point_side == Side::kMobile ? Fundamental::angle(u_a, u_b, v, 0)
                                     : Fundamental::angle(u_b, u_a, v, 0);
}

inline void one(RuleOutput& out, const Fundamental& f) { out.addAlternative().push_back(f); }
inline void two(RuleOutput& out, const Fundamental& f, const Fundamental& g) {
  Alt& a = out.addAlternative();
  a.push_back(f);
  a.push_back(g);
}

// acos of a ratio that must lie in [-1, 1] up to tolerance; false when it does not.
inline bool acosChecked(double num, double den, double tol, double* angle) {
  double c = num / den;
  if (std::abs(num) > den + tol) return false;
  *angle = std::acos(c > 1 ? 1 : (c < -1 ? -1 : c));
  return true;
}

}  // namespace relpos::rules::detail
