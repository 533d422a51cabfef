#pragma once
// What PMF App. IV Tables VIII and IX share (pl_lp.cpp, pl_planep.cpp): a point of object a on a
// line of object b, and a point of b on a line (VIII) or plane (IX) of a. With P_a on a's own
// line/plane and Q_b on K_b (the d_a = d_b = 0 rows), either the two points coincide or K_b lies
// along a's line (VIII) / in a's plane (IX).
#include "rule_helpers.hpp"

namespace relpos::rules::detail {

// The one case of each of the two families.
enum MixedRoleCase { kPointsOrLines };

// `x` = d(P_a, K_b) = 0 (point side a), `y` = Q_b on a's line or plane (point side b).
inline void pointsOrLines(const Fundamental& x, const Fundamental& y, bool plane,
                          const Tolerance& tol, RuleOutput& out) {
  if (sameRoles(x, y) || !tol.zeroLength(x.value()) || !tol.zeroLength(y.value())) return;
  // P_a = x.p lies on a's element (y.q, y.d)?  Q_b = y.p lies on K_b = (x.q, x.d)?
  const Vector3d w = x.p - y.q;
  const double da = plane ? std::abs(w.dot(y.d)) : (w - w.dot(y.d) * y.d).norm();
  const Vector3d v = y.p - x.q;
  const double db = (v - v.dot(x.d) * x.d).norm();
  if (da > tol.length || db > tol.length) return;
  out.fire(kPointsOrLines);
  // First solution: the two points coincide.
  one(out, pinPoint(x, y.p));
  // Second: K_b along a's line (either way) or inside a's plane; Q_b on a's element then follows.
  const Side side = x.point_side;  // a's side
  if (plane) return two(out, x, angleAB(side, y.d, x.d, kPi / 2));
  two(out, x, angleAB(side, y.d, x.d, 0.0));
  two(out, x, angleAB(side, y.d, x.d, kPi));
}

}  // namespace relpos::rules::detail
