// PMF App. IV Table II: a point-point and a point-line distance, d(P_a, P_b) = p,
// d(Q_a, L_b) = q. "a" is the object owning Q (the point-line constraint's point side); a
// point-point distance reads the same from either object. d_a = |P_a Q_a|, d_b = distance(P_b,
// L_b), Q_b = the foot of P_b on L_b, u_b = P_bQ_b / d_b. Rows with p = 0 are the pinned-point
// rules (pinned_point.cpp).
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp_pl_family {
using namespace detail;

enum Case {
  kIncompatible,
  kCirclesAboutAxis,
  kSphereMeetsLine,
  kTangent,
  kCollinear,
  kExtremeOnAxis
};

void pointPointAndPointLine(const Fundamental& pp, const Fundamental& pl, const Tolerance& tol,
                            RuleOutput& out) {
  const double p = pp.value(), q = pl.value();
  if (tol.zeroLength(p)) return;  // pinned-point rules
  const bool a_mobile = pl.point_side == Side::kMobile;
  const Vector3d P_a = a_mobile ? pp.p : pp.q;  // the point-point constraint's point on side a
  const Vector3d P_b = a_mobile ? pp.q : pp.p;
  const Vector3d& Q_a = pl.p;
  const Vector3d Q_b = projectOnLine(P_b, pl.q, pl.d);
  const double da = (Q_a - P_a).norm(), db = (Q_b - P_b).norm();
  const double eps = tol.length;
  if (db - da > p + q + eps || da + db < q - p - eps)
    return out.fire(kIncompatible)
        .incompatible(
            "a point-point and a point-line distance that no pose satisfies (PMF App. IV Table II, "
            "row 1)");
  const bool za = da <= eps, zb = db <= eps;
  // One point: on a sphere about P_b and a cylinder about L_b.
  if (za && zb && !tol.zeroLength(q)) {
    // The sphere's centre is on the axis: one circle (p = q) or two (p > q) ⊥ L_b.
    out.fire(kCirclesAboutAxis);
    // A centre db off the axis (within the tolerance) tilts the circles: their height ±k varies
    // by about q db / k around the axis, and by (p + q) δ / k with p and q known to δ; where the
    // sphere barely reaches beyond the cylinder (k small), by sqrt(2 (p + q) (δ + db)). The planes
    // carry that (Fundamental::err).
    const double at_tangent = std::sqrt(2 * (p + q) * (eps + db));
    if (tol.equalLength(p, q)) return two(out, pl, withErr(onPlane(pl, P_b, pl.d), at_tangent));
    const double k = std::sqrt(p * p - q * q);
    const double err = std::min(((p + q) * eps + q * db) / k, at_tangent);
    two(out, pl, withErr(onPlane(pl, P_b + k * pl.d, pl.d), err));
    two(out, pl, withErr(onPlane(pl, P_b - k * pl.d, pl.d), err));
    return;
  }
  if (za && tol.zeroLength(q)) {
    // The point on the line at p from P_b: one or two points.
    Vector3d x[2];
    double err = 0.0;
    const int n = lineSphere(pl.q, pl.d, P_b, p, tol, x, &err);
    if (n == 0) return out.fire(kIncompatible).incompatible("the line does not reach the sphere");
    out.fire(kSphereMeetsLine);
    for (int k = 0; k < n; ++k) one(out, withErr(pinPoint(pl, x[k]), err));
    return;
  }
  if (zb) {
    if (!za && tol.equalLength(da, q - p)) {
      // Both points on one radius of the axis: R_a = P_a − p u_a sits on P_b, u_a ⊥ L_b.
      const Vector3d u_a = (Q_a - P_a) / da;
      return two(out.fire(kExtremeOnAxis), pinPointAt(pl, P_a - p * u_a, P_b),
                 angleAB(pl.point_side, u_a, pl.d, kPi / 2));
    }
    return;
  }
  const Vector3d u_b = (Q_b - P_b) / db;
  if (za) {
    if (tol.equalLength(db, p + q)) return one(out.fire(kTangent), pinPoint(pl, P_b + p * u_b));
    if (tol.equalLength(db, q - p)) return one(out.fire(kTangent), pinPoint(pl, P_b - p * u_b));
    return;
  }
  if (tol.equalLength(db - da, p + q))
    return two(out.fire(kCollinear), pinPointAt(pl, P_a, P_b + p * u_b),
               pinPoint(pl, Q_b - q * u_b));
  if (tol.equalLength(da + db, q - p))
    return two(out.fire(kCollinear), pinPointAt(pl, P_a, P_b - p * u_b),
               pinPoint(pl, Q_b - q * u_b));
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table II, row 1"},
    {kCirclesAboutAxis, "circles-about-axis",
     "PMF App. IV Table II, rows 3 and 4 (p >= q, d_a = d_b = 0)"},
    {kSphereMeetsLine, "sphere-meets-line",
     "PMF App. IV Table II, row 11 (d_b < p, d_a = 0, q = 0)"},
    {kTangent, "tangent", "PMF App. IV Table II, rows 8 and 9 (d_a = 0)"},
    {kCollinear, "collinear", "PMF App. IV Table II, rows 7 and 10 (d_a, d_b ≠ 0)"},
    {kExtremeOnAxis, "extreme-on-axis", "PMF App. IV Table II, row 6 (d_a = q − p, d_b = 0)"}};

}  // namespace pp_pl_family

constexpr RuleFamily families::pp_pl = family(
    "pp+pl", "PMF App. IV Table II", FundamentalKind::kPointPoint, FundamentalKind::kPointLine,
    &pp_pl_family::withLengthErr<pp_pl_family::pointPointAndPointLine>, pp_pl_family::kCases);

}  // namespace relpos::rules
