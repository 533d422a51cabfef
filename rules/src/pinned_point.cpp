// A pinned mobile point d(P_m, P_f) = 0 with one more translational constraint. With P pinned,
// T = P_f − R P_m, so any constraint on another point Q becomes a condition on the rotation of
// u = Q_m − P_m alone: an angle, two angles, or two pins. These generalise the p = 0 rows of PMF
// App. IV Tables I, II, V, VI, VIII and IX (derived from the geometry; the tables list special
// cases).
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

// Case indices: 0 and 1 in every family; 2 is the angle (pp0+pp, pp0+pplane) or the cone (pp0+pl).
enum Case { kIncompatible = 0, kImplied = 1, kAngle = 2, kCone = 2, kPoints = 3, kThrough = 4 };

bool pinned(const Fundamental& f, const Tolerance& tol) {
  return f.kind == FundamentalKind::kPointPoint && tol.zeroLength(f.value());
}

const char* kOutOfReach = "with one point pinned, the other constraint is out of reach";
const char* kSamePoint = "a pinned point that violates another constraint on the same point";

// The other constraint holds (drop it) or cannot hold.
void impliedOrIncompatible(bool holds, RuleOutput& out, bool drop_first = false) {
  if (!holds) return out.fire(kIncompatible).incompatible(kSamePoint);
  out.fire(kImplied);
  if (drop_first)
    out.redundantFirst();
  else
    out.redundantSecond();
}

// Replaces {pin, b} by {pin, ∠(u_m, w_f) = acos(c)}, c known to ±dc and the vectors to ±dir_err.
void pinAngle(const Fundamental& pin, const Vector3d& u_m, const Vector3d& w_f, double c, double dc,
              double dir_err, RuleOutput& out) {
  two(out.fire(kAngle), pin,
      withErr(Fundamental::angle(u_m, w_f, std::acos(clampUnit(c)), 0),
              acosSpread(c, dc) + dir_err));
}

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

// The span `len` long (from the pin to the other point) at height h over a plane through the pin
// (its normal being the other vector): ∠ = acos(h / len).
void pinPlaneAngle(const Fundamental& pin, const Vector3d& u_m, const Vector3d& w_f, double h,
                   double len, const Tolerance& tol, RuleOutput& out) {
  if (std::abs(h) > len + tol.length) return out.fire(kIncompatible).incompatible(kOutOfReach);
  two(out.fire(kAngle), pin,
      withErr(Fundamental::angle(u_m, w_f, std::acos(clampUnit(h / len)), 0),
              heightAngleErr(h, len, tol)));
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
    return impliedOrIncompatible(tol.equalLength(std::max(nu, nw), q), out, !a_pin);
  // Q reaches from |nu − nw| (R u along w) to nu + nw (against it): decided in lengths, not on
  // the cosine below, whose units are lengths squared.
  if (q < std::abs(nu - nw) - tol.length || q > nu + nw + tol.length)
    return out.fire(kIncompatible).incompatible(kOutOfReach);
  const double c = 0.5 * (nu * nu + nw * nw - q * q) / (nu * nw);
  // Each of q, |u|, |w| known to the length tolerance moves c by at most that over |u||w|.
  const double dc = tol.length * (q + nu + nw) / (nu * nw);
  pinAngle(pin, u / nu, w / nw, c, dc, spanErr(nu, tol) + spanErr(nw, tol), out);
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
    if (nu <= tol.length) return impliedOrIncompatible(tol.equalLength(e.norm(), q), out);
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
  if (nw <= tol.length) return impliedOrIncompatible(tol.equalLength(ne, q), out);
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

void pinnedWithPointPlane(const Fundamental& pin, const Fundamental& b, const Tolerance& tol,
                          RuleOutput& out) {
  if (!pinned(pin, tol)) return;
  if (b.point_side == Side::kMobile) {
    // (P_f + R u − c)·n = 0  <=>  R u · n = (c − P_f)·n.
    const Vector3d u = b.p - pin.p;
    const double h = (b.q - pin.q).dot(b.d), nu = u.norm();
    if (nu <= tol.length) return impliedOrIncompatible(tol.zeroLength(h), out);
    return pinPlaneAngle(pin, u / nu, b.d, h, nu, tol, out);
  }
  // Fixed Q_f on the mobile plane (c_m, n_m): (Q_f − P_f)·R n_m = (c_m − P_m)·n_m.
  const Vector3d w = b.p - pin.q;
  const double h = (b.q - pin.p).dot(b.d), nw = w.norm();
  if (nw <= tol.length) return impliedOrIncompatible(tol.zeroLength(h), out);
  pinPlaneAngle(pin, b.d, w / nw, h, nw, tol, out);
}

}  // namespace

void registerPinnedPointRules(Registry& r) {
  using FK = FundamentalKind;
  addFamily(r, "pp0+pp", "PMF App. IV Table I, rows with q = 0 (generalised)", FK::kPointPoint,
            FK::kPointPoint, &withLengthErr<pinnedWithPointPoint>,
            {{"pp0+pp/incompatible", "PMF App. IV Table I, row 1 with q = 0"},
             {"pp0+pp/implied", "PMF App. IV Table I, row 2 with q = 0"},
             {"pp0+pp/angle", "PMF App. IV Table I, row 5 (generalised: law of cosines)"}});
  addFamily(r, "pp0+pl", "PMF App. IV Tables II and VIII, p = 0 rows (generalised)",
            FK::kPointPoint, FK::kPointLine, &withLengthErr<pinnedWithPointLine>,
            {{"pp0+pl/incompatible", "PMF App. IV Table II, row 1 with p = 0"},
             {"pp0+pl/implied", "PMF App. IV Table II, row 2"},
             {"pp0+pl/cone", "PMF App. IV Table II, row 4 (d_a > q, d_b = 0, p = 0)"},
             {"pp0+pl/points", "PMF App. IV Table II, row 10 (d_b < d_a, p = q = 0)"},
             {"pp0+pl/line-through-point", "PMF App. IV Table VIII, p = 0 rows (generalised)"}});
  addFamily(r, "pp0+pplane", "PMF App. IV Tables V and IX, p = 0 rows (generalised)",
            FK::kPointPoint, FK::kPointPlane, &withLengthErr<pinnedWithPointPlane>,
            {{"pp0+pplane/incompatible", "PMF App. IV Table V, row 1 with p = 0"},
             {"pp0+pplane/implied", "PMF App. IV Table V, row 2 with p = 0"},
             {"pp0+pplane/angle", "PMF App. IV Table V, rows 5 and 6 (generalised)"}});
}

}  // namespace relpos::rules
