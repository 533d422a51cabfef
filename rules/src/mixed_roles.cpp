// PMF App. IV Tables VIII and IX: a point of object a on a line of object b, and a point of b on
// a line (VIII) or plane (IX) of a. With P_a on a's own line/plane and Q_b on K_b (the d_a = d_b
// = 0 rows), either the two points coincide or K_b lies along a's line (VIII) / in a's plane (IX).
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

enum Case { kPointsOrLines };

// `x` = d(P_a, K_b) = 0 (point side a), `y` = Q_b on a's line or plane (point side b).
// Returns P_a, Q_b and the direction / normal of a's element in a common reading.
void pointsOrLines(const Fundamental& x, const Fundamental& y, bool plane, const Tolerance& tol,
                   RuleOutput& out) {
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

void lineLine(const Fundamental& x, const Fundamental& y, const Tolerance& tol, RuleOutput& out) {
  if (x.point_side == Side::kMobile) return pointsOrLines(x, y, false, tol, out);
  pointsOrLines(y, x, false, tol, out);
}

void linePlane(const Fundamental& x, const Fundamental& y, const Tolerance& tol, RuleOutput& out) {
  pointsOrLines(x, y, true, tol, out);
}

}  // namespace

void registerMixedRoleRules(Registry& r) {
  using FK = FundamentalKind;
  addFamily(r, "pl+lp", "PMF App. IV Table VIII", FK::kPointLine, FK::kPointLine, &lineLine,
            {{"pl+lp/points-or-lines", "PMF App. IV Table VIII, row 1"}});
  addFamily(r, "pl+planep", "PMF App. IV Table IX", FK::kPointLine, FK::kPointPlane, &linePlane,
            {{"pl+planep/points-or-plane", "PMF App. IV Table IX, row 1"}});
}

}  // namespace relpos::rules
