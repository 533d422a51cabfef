// PMF App. IV Table I: two point-point distance constraints d(P_a, P_b) = p, d(Q_a, Q_b) = q.
// a = the mobile object, b = the fixed one; d_a = |P_a Q_a|, d_b = |P_b Q_b|.
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

void twoPointPoint(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out) {
  const double p = a.value(), q = b.value();
  const double da = (b.p - a.p).norm(), db = (b.q - a.q).norm();
  const double eps = tol.length;
  // Row 1: incompatible.
  if (da + db < std::abs(p - q) - eps || std::abs(db - da) > p + q + eps)
    return out.incompatible("two point-point distances that no pose satisfies (PMF App. IV "
                            "Table I, row 1)");
  const bool za = da <= eps, zb = db <= eps;
  // Row 2: the same two points twice.
  if (za && zb) {
    out.verdict = RuleVerdict::kRedundantSecond;
    return;
  }
  const Vector3d u_b = zb ? Vector3d::Zero() : Vector3d((b.q - a.q) / db);
  if (za) {
    // One mobile point at p from P_b and q from Q_b: a point (tangent spheres) or a circle.
    if (tol.zeroLength(p) || tol.zeroLength(q)) return;  // pinned-point rules decide
    if (tol.equalLength(db, p + q)) return one(out, pinPoint(a, a.q + p * u_b));
    if (tol.equalLength(db, std::abs(p - q)))
      return one(out, pinPoint(a, a.q + (p > q ? p : -p) * u_b));
    const double k = (db * db + p * p - q * q) / (2 * db);
    const double r = std::sqrt(std::max(0.0, p * p - k * k));
    return two(out, onLine(a, a.q, u_b, r), onPlane(a, a.q + k * u_b, u_b));
  }
  if (zb) return;
  // Row 7: two pinned points at equal spans: the rotation keeps P_aQ_a along P_bQ_b.
  if (tol.zeroLength(p) && tol.zeroLength(q)) {
    const Vector3d u_a = (b.p - a.p) / da;
    return two(out, a, Fundamental::angle(u_a, u_b, 0.0, 0));
  }
  // Rows 3 and 6: the four points on one line.
  if (tol.equalLength(da + db, std::abs(p - q)) && !tol.zeroLength(p - q)) {
    const double s = p > q ? 1.0 : -1.0;
    return two(out, pinPoint(a, a.q + s * p * u_b), pinPoint(b, b.q + s * q * u_b));
  }
  if (tol.equalLength(db - da, p + q) && !tol.zeroLength(p + q))
    return two(out, pinPoint(a, a.q + p * u_b), pinPoint(b, b.q - q * u_b));
}

}  // namespace

void registerPointPointRules(Registry& r) {
  r.addRule({"pp+pp/two-distances", "PMF App. IV Table I (all rows; row 4 = circle)",
             FundamentalKind::kPointPoint, FundamentalKind::kPointPoint, &twoPointPoint});
}

}  // namespace relpos::rules
