// PMF App. IV Table III: two point-line distances d(P_a, K_b) = p, d(P_a, L_b) = q on the same
// point P_a (the worked example's "lines meet" rule, 003 §VI-A). Rows for different points
// (Tables III–IV with d_a ≠ 0) come with the complete rule set.
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

// Points of line (c, d) at distance q from line (c2, d2) when the lines are skew or meet: the
// distance from c + t d to the other line is sqrt(db² + t² sin²θ) measured from the common
// perpendicular's foot (derived from the geometry: the table's k omits the 1/sinθ factor).
void pointsOnLineAtDistance(const Fundamental& a, const Vector3d& foot, const Vector3d& d,
                            double sin_theta, double db, double q, const Tolerance& tol,
                            RuleOutput& out) {
  if (q < db - tol.length)
    return out.incompatible("a point on one line cannot reach the required distance from the "
                            "other line (PMF App. IV Table III)");
  if (tol.equalLength(q, db)) return one(out, pinPoint(a, foot));
  const double t = std::sqrt(q * q - db * db) / sin_theta;
  one(out, pinPoint(a, foot + t * d));
  one(out, pinPoint(a, foot - t * d));
}

void samePointTwoLines(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                       RuleOutput& out) {
  if (a.point_side != b.point_side || (a.p - b.p).norm() > tol.length) return;
  const double p = a.value(), q = b.value();
  const Vector3d cross = a.d.cross(b.d);
  const double sin_theta = cross.norm();
  if (tol.parallelUnit(sin_theta)) {
    // Parallel lines: coaxial cylinders (redundant or incompatible) or up to two lines.
    Vector3d w = b.q - a.q;
    Vector3d w_perp = w - w.dot(a.d) * a.d;
    const double db = w_perp.norm();
    if (db <= tol.length) {
      if (tol.equalLength(p, q)) {
        out.verdict = RuleVerdict::kRedundantSecond;
        return;
      }
      return out.incompatible("one point at two different distances from the same line");
    }
    if (db > p + q + tol.length || db < std::abs(p - q) - tol.length)
      return out.incompatible("one point at distances from two parallel lines that cannot be met "
                              "together (PMF App. IV Table III, row 1)");
    const Vector3d u_b = w_perp / db;
    const Vector3d v_b = a.d.cross(u_b);
    const double k1 = (db * db + p * p - q * q) / (2 * db);
    const double k2sq = p * p - k1 * k1;
    if (k2sq <= 2 * tol.length * std::max(1.0, p)) return one(out, onLine(a, a.q + k1 * u_b, a.d, 0));
    const double k2 = std::sqrt(k2sq);
    one(out, onLine(a, a.q + k1 * u_b + k2 * v_b, a.d, 0));
    one(out, onLine(a, a.q + k1 * u_b - k2 * v_b, a.d, 0));
    return;
  }
  Vector3d f1, f2;
  closestPointsOfLines(a.q, a.d, b.q, b.d, 0.0, &f1, &f2);
  const double db = (f2 - f1).norm();
  const bool p0 = tol.zeroLength(p), q0 = tol.zeroLength(q);
  if (p0 && q0) {
    if (db <= tol.length) return one(out, pinPoint(a, 0.5 * (f1 + f2)));  // K ∩ L
    return out.incompatible("a point on two lines that do not meet (PMF App. IV Table III)");
  }
  if (p0) return pointsOnLineAtDistance(a, f1, a.d, sin_theta, db, q, tol, out);
  if (q0) return pointsOnLineAtDistance(a, f2, b.d, sin_theta, db, p, tol, out);
  if (db > p + q + tol.length)
    return out.incompatible("a point at distances from two lines that are too far apart");
  if (tol.equalLength(db, p + q)) return one(out, pinPoint(a, f1 + (p / db) * (f2 - f1)));
}

}  // namespace

void registerPointLineRules(Registry& r) {
  r.addRule({"pl+pl/same-point", "PMF App. IV Table III (d_a = 0 rows; lines meet: 003 §VI-A)",
             FundamentalKind::kPointLine, FundamentalKind::kPointLine, &samePointTwoLines});
}

}  // namespace relpos::rules
