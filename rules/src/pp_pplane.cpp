// PMF App. IV Table V: a point-point distance and a point-plane coincidence,
// d(P_a, P_b) = p, d(Q_a, Π_b) = 0. "a" owns Q (the point-plane constraint's point side);
// d_a = |P_a Q_a|, d_b = distance(P_b, Π_b), Q_b = the foot of P_b on Π_b, u_b = P_bQ_b / d_b.
// Rows with p = 0 are the pinned-point rules (pinned_point.cpp).
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp_pplane_family {
using namespace detail;

enum Case { kIncompatible, kCircle, kTangent, kStretched };

void pointPointAndPointPlane(const Fundamental& pp, const Fundamental& pl, const Tolerance& tol,
                             RuleOutput& out) {
  const double p = pp.value();
  if (tol.zeroLength(p)) return;  // pinned-point rules
  const bool a_mobile = pl.point_side == Side::kMobile;
  const Vector3d P_a = a_mobile ? pp.p : pp.q;
  const Vector3d P_b = a_mobile ? pp.q : pp.p;
  const Vector3d& Q_a = pl.p;
  const double h = (P_b - pl.q).dot(pl.d);  // signed height of P_b over the plane
  const Vector3d Q_b = P_b - h * pl.d;
  const double da = (Q_a - P_a).norm(), db = std::abs(h);
  if (db - da > p + tol.length)
    return out.fire(kIncompatible)
        .incompatible(
            "a point-point distance and a point-plane coincidence that no pose satisfies (PMF App. "
            "IV Table V, row 1)");
  if (da <= tol.length) {
    // One point on a sphere and a plane: the circle about the normal through P_b, or the tangent
    // point (also where the plane passes beyond the sphere by no more than the tolerance: the
    // check above allowed it, and the circle's radius would be the root of a negative).
    if (db >= p - tol.length) return one(out.fire(kTangent), pinPoint(pl, Q_b));
    const double k = std::sqrt(p * p - db * db);
    return two(out.fire(kCircle), onLine(pl, P_b, pl.d, k), pl);
  }
  if (db > tol.length && tol.equalLength(db - da, p)) {
    // P_b, P_a, Q_a, Q_b on the normal through P_b.
    const Vector3d u_b = (Q_b - P_b) / db;
    return two(out.fire(kStretched), pinPointAt(pl, P_a, P_b + p * u_b), pinPoint(pl, Q_b));
  }
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table V, row 1"},
    {kCircle, "circle", "PMF App. IV Table V, row 4 (d_b < p, d_a = 0)"},
    {kTangent, "tangent", "PMF App. IV Table V, row 2 (d_b = p, d_a = 0)"},
    {kStretched, "stretched", "PMF App. IV Table V, row 3 (d_b − d_a = p)"}};

}  // namespace pp_pplane_family

constexpr RuleFamily families::pp_pplane = family(
    "pp+pplane", "PMF App. IV Table V", FundamentalKind::kPointPoint, FundamentalKind::kPointPlane,
    &pp_pplane_family::withLengthErr<pp_pplane_family::pointPointAndPointPlane>,
    pp_pplane_family::kCases);

}  // namespace relpos::rules
