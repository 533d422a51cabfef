// PMF App. IV Table I: two point-point distance constraints d(P_a, P_b) = p, d(Q_a, Q_b) = q.
// a = the mobile object, b = the fixed one; d_a = |P_a Q_a|, d_b = |P_b Q_b|, u_b = P_bQ_b / d_b.
// (The rows with p = 0 or q = 0 and d_a ≠ 0 are the pinned-point rules, pinned_point.cpp.)
#include <algorithm>
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp_pp_family {
using namespace detail;

enum Case { kIncompatible, kSamePoints, kTangentSpheres, kCircle, kCollinear, kEqualSpan };

void twoPointPoint(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out) {
  const double p = a.value(), q = b.value();
  const double da = (b.p - a.p).norm(), db = (b.q - a.q).norm();
  const double eps = tol.length;
  if (da + db < std::abs(p - q) - eps || std::abs(db - da) > p + q + eps)
    return out.fire(kIncompatible)
        .incompatible(
            "two point-point distances that no pose satisfies (PMF App. IV Table I, row 1)");
  const bool za = da <= eps, zb = db <= eps;
  if (za && zb) return out.fire(kSamePoints).redundantSecond();  // p = q, else row 1
  if (zb) return;  // two points about one centre: no single-constraint rule
  const Vector3d u_b = (b.q - a.q) / db;
  if (za) {
    // One mobile point at p from P_b and q from Q_b.
    if (tol.zeroLength(p) || tol.zeroLength(q)) return;  // pinned-point rules
    // Nearly concentric spheres: where they meet is known to rounding × max(p, q) / d_b.
    if (tol.tooIllConditioned(std::max(p, q) / db)) return out.defer();
    // Row 4: the circle where the spheres meet, in the plane ⊥ u_b at k from P_b. They touch
    // (rows 3 and 5) when the circle is within the tolerance of a point: decided on its radius,
    // not on d_b − (p ± q), which for nearly concentric spheres can be within the tolerance while
    // the circle is large.
    const double k = (db * db + p * p - q * q) / (2 * db);
    const double r2 = p * p - k * k;
    if (r2 <= 2.0 * tol.length * std::max(p, q))
      return one(out.fire(kTangentSpheres), pinPoint(a, a.q + std::clamp(k, -p, p) * u_b));
    return two(out.fire(kCircle), onLine(a, a.q, u_b, std::sqrt(r2)),
               onPlane(a, a.q + k * u_b, u_b));
  }
  if (tol.zeroLength(p) && tol.zeroLength(q)) {
    // Row 7: both points pinned, equal spans: P pinned and P_aQ_a kept along P_bQ_b.
    const Vector3d u_a = (b.p - a.p) / da;
    return two(out.fire(kEqualSpan), a,
               withErr(Fundamental::angle(u_a, u_b, 0.0, 0), spanErr(da, tol) + spanErr(db, tol)));
  }
  // Rows 3 and 6: the extreme configurations put all four points on one line.
  if (tol.equalLength(da + db, std::abs(p - q)) && !tol.zeroLength(p - q)) {
    const double s = p > q ? 1.0 : -1.0;
    return two(out.fire(kCollinear), pinPoint(a, a.q + s * p * u_b),
               pinPoint(b, b.q + s * q * u_b));
  }
  if (tol.equalLength(db - da, p + q))
    return two(out.fire(kCollinear), pinPoint(a, a.q + p * u_b), pinPoint(b, b.q - q * u_b));
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table I, row 1"},
    {kSamePoints, "same-points", "PMF App. IV Table I, row 2"},
    {kTangentSpheres, "tangent-spheres", "PMF App. IV Table I, rows 3 and 5 (d_a = 0)"},
    {kCircle, "circle", "PMF App. IV Table I, row 4"},
    {kCollinear, "collinear", "PMF App. IV Table I, rows 3 and 6 (d_a ≠ 0)"},
    {kEqualSpan, "equal-span", "PMF App. IV Table I, row 7"}};

}  // namespace pp_pp_family

constexpr RuleFamily families::pp_pp = family(
    "pp+pp", "PMF App. IV Table I", FundamentalKind::kPointPoint, FundamentalKind::kPointPoint,
    &pp_pp_family::withLengthErr<pp_pp_family::twoPointPoint>, pp_pp_family::kCases);

}  // namespace relpos::rules
