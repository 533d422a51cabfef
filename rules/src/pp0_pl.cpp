// PMF App. IV Tables II and VIII, p = 0 rows (generalised): a pinned mobile point and a
// point-line distance on another point, a condition on the rotation alone (pinned.hpp).
#include <algorithm>
#include <cmath>

#include "family.hpp"
#include "pinned.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp0_pl_family {
using namespace detail;

enum Case { kIncompatible, kImplied, kCone, kPoints, kThrough };

// Two cones: the angle between a mobile vector and a fixed one is asin(s) or π − asin(s), with
// s = num / den (lengths, den the span of the vector u_m or w_f that was derived from lengths).
void pinSinCone(const Fundamental& pin, const Vector3d& u_m, const Vector3d& w_f, double num,
                double den, const Tolerance& tol, RuleOutput& out) {
  if (num > den + tol.length) return out.fire(kIncompatible).incompatible(kOutOfReach);
  const double s = std::min(1.0, num / den);
  const double a = std::asin(s);
  const double err = asinSpread(s, tol.length * (1.0 + s) / den) + spanErr(den, tol);
  out.fire(kCone);
  if (std::abs(a - kPi / 2) <= tol.angle + err)
    return two(out, pin, withErr(Fundamental::angle(u_m, w_f, kPi / 2, 0), err));
  two(out, pin, withErr(Fundamental::angle(u_m, w_f, a, 0), err));
  two(out, pin, withErr(Fundamental::angle(u_m, w_f, kPi - a, 0), err));
}

void pinnedWithPointLine(const Fundamental& pin, const Fundamental& b, const Tolerance& tol,
                         RuleOutput& out) {
  if (!pinned(pin, tol)) return;
  const double q = b.value();
  if (b.point_side == Side::kMobile) {
    // |(P_f + R u − c) × d| = q with u = Q_m − P_m and the fixed line (c, d).
    const Vector3d u = b.p - pin.p;
    const Vector3d e = (pin.q - b.q) - (pin.q - b.q).dot(b.d) * b.d;
    const double nu = u.norm();
    if (nu <= tol.length) return impliedOrIncompatible<Case>(tol.equalLength(e.norm(), q), out);
    if (e.norm() <= tol.length) return pinSinCone(pin, u / nu, b.d, q, nu, tol, out);
    if (!tol.zeroLength(q)) return;  // Q on a circle: no single-angle rule
    // Q on the line at |u| from the pin (Table II, row "d_b < d_a, p = q = 0"): one or two pins.
    Vector3d x[2];
    double err = 0.0;
    const int n = lineSphere(b.q, b.d, pin.q, nu, tol, x, &err);
    if (n == 0) return out.fire(kIncompatible).incompatible(kOutOfReach);
    out.fire(kPoints);
    for (int k = 0; k < n; ++k) two(out, pin, withErr(pinPoint(b, x[k]), err));
    return;
  }
  // Fixed point Q_f at distance q from the mobile line (c_m, d_m): |(Rᵀw − (c_m − P_m)) × d_m| = q.
  const Vector3d w = b.p - pin.q;
  const Vector3d e = (b.q - pin.p) - (b.q - pin.p).dot(b.d) * b.d;
  const double nw = w.norm(), ne = e.norm();
  if (nw <= tol.length) return impliedOrIncompatible<Case>(tol.equalLength(ne, q), out);
  if (ne <= tol.length) return pinSinCone(pin, b.d, w / nw, q, nw, tol, out);
  if (!tol.zeroLength(q)) return;
  // The mobile line passes at e from the pinned point; it must carry Q_f, at |w| from the pin:
  // its points e ± k d (k = sqrt(|w|² − |e|²)) are the ones R can lay onto w (derived from the
  // geometry): one parallelism per point.
  if (nw < ne - tol.length) return out.fire(kIncompatible).incompatible(kOutOfReach);
  const double k = nw > ne ? std::sqrt(nw * nw - ne * ne) : 0.0;
  // k from |w| and |e|, each known to the tolerance (a root: steep where k is small).
  const double dk = tol.length * (nw + ne) / std::max(k, std::sqrt(2.0 * tol.length * nw));
  const double err = (tol.length + dk) / nw + spanErr(nw, tol);
  out.fire(kThrough);
  if (k <= tol.length)
    return two(out, pin, withErr(Fundamental::angle(e / ne, w / nw, 0.0, 0), err));
  two(out, pin, withErr(Fundamental::angle((e + k * b.d).normalized(), w / nw, 0.0, 0), err));
  two(out, pin, withErr(Fundamental::angle((e - k * b.d).normalized(), w / nw, 0.0, 0), err));
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table II, row 1 with p = 0"},
    {kImplied, "implied", "PMF App. IV Table II, row 2"},
    {kCone, "cone", "PMF App. IV Table II, row 4 (d_a > q, d_b = 0, p = 0)"},
    {kPoints, "points", "PMF App. IV Table II, row 10 (d_b < d_a, p = q = 0)"},
    {kThrough, "line-through-point", "PMF App. IV Table VIII, p = 0 rows (generalised)"}};

}  // namespace pp0_pl_family

constexpr RuleFamily families::pp0_pl = family(
    "pp0+pl", "PMF App. IV Tables II and VIII, p = 0 rows (generalised)",
    FundamentalKind::kPointPoint, FundamentalKind::kPointLine,
    &pp0_pl_family::withLengthErr<pp0_pl_family::pinnedWithPointLine>, pp0_pl_family::kCases);

}  // namespace relpos::rules
