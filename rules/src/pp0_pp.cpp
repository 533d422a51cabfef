// PMF App. IV Table I, rows with q = 0 (generalised): a pinned mobile point and a second
// point-point distance, |R u − w| = q for u, w the other points' offsets from the pin (pinned.hpp).
#include <algorithm>
#include <cmath>

#include "family.hpp"
#include "pinned.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp0_pp_family {
using namespace detail;

enum Case { kIncompatible, kImplied, kAngle };

// Replaces {pin, b} by {pin, ∠(u_m, w_f) = acos(c)}, c known to ±dc and the vectors to ±dir_err.
void pinAngle(const Fundamental& pin, const Vector3d& u_m, const Vector3d& w_f, double c, double dc,
              double dir_err, RuleOutput& out) {
  two(out.fire(kAngle), pin,
      withErr(Fundamental::angle(u_m, w_f, std::acos(clampUnit(c)), 0),
              acosSpread(c, dc) + dir_err));
}

void pinnedWithPointPoint(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                          RuleOutput& out) {
  // Both pinned, or neither: Table I decides.
  if (pinned(a, tol) == pinned(b, tol)) return;
  const bool a_pin = pinned(a, tol);
  const Fundamental& pin = a_pin ? a : b;
  const Fundamental& o = a_pin ? b : a;
  const Vector3d u = o.p - pin.p, w = o.q - pin.q;
  const double nu = u.norm(), nw = w.norm(), q = o.value();
  // |R u − w| = q  <=>  R u · w = (|u|² + |w|² − q²) / 2.
  if (nu <= tol.length || nw <= tol.length)
    return impliedOrIncompatible<Case>(tol.equalLength(std::max(nu, nw), q), out, !a_pin);
  // Q reaches from |nu − nw| (R u along w) to nu + nw (against it): decided in lengths, not on
  // the cosine below, whose units are lengths squared.
  if (q < std::abs(nu - nw) - tol.length || q > nu + nw + tol.length)
    return out.fire(kIncompatible).incompatible(kOutOfReach);
  const double c = 0.5 * (nu * nu + nw * nw - q * q) / (nu * nw);
  // Each of q, |u|, |w| known to the length tolerance moves c by at most that over |u||w|.
  const double dc = tol.length * (q + nu + nw) / (nu * nw);
  pinAngle(pin, u / nu, w / nw, c, dc, spanErr(nu, tol) + spanErr(nw, tol), out);
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table I, row 1 with q = 0"},
    {kImplied, "implied", "PMF App. IV Table I, row 2 with q = 0"},
    {kAngle, "angle", "PMF App. IV Table I, row 5 (generalised: law of cosines)"}};

}  // namespace pp0_pp_family

constexpr RuleFamily families::pp0_pp = family(
    "pp0+pp", "PMF App. IV Table I, rows with q = 0 (generalised)", FundamentalKind::kPointPoint,
    FundamentalKind::kPointPoint,
    &pp0_pp_family::withLengthErr<pp0_pp_family::pinnedWithPointPoint>, pp0_pp_family::kCases);

}  // namespace relpos::rules
