#pragma once
// Helpers shared by the rule families: building results on the same sides as the inputs, and the
// small geometric facts several PMF tables use.
#include <algorithm>
#include <cmath>

#include "relpos/core/registry.hpp"
#include "relpos/core/rule.hpp"

namespace relpos::rules::detail {

using Alt = FixedVector<Fundamental, kMaxRuleOutputs>;

// d(a's point, X) = 0 where X is a point on the other side of a.
inline Fundamental pinPoint(const Fundamental& a, const Vector3d& x) {
  return a.point_side == Side::kMobile ? Fundamental::pointPoint(a.p, x, 0.0, a.sources)
                                       : Fundamental::pointPoint(x, a.p, 0.0, a.sources);
}
// d(point p of a's side, X) = 0: a pin for another point of the same side as a.
inline Fundamental pinPointAt(const Fundamental& a, const Vector3d& p, const Vector3d& x) {
  return a.point_side == Side::kMobile ? Fundamental::pointPoint(p, x, 0.0, a.sources)
                                       : Fundamental::pointPoint(x, p, 0.0, a.sources);
}
inline Fundamental onLine(const Fundamental& a, const Vector3d& c, const Vector3d& d, double v) {
  return Fundamental::pointLine(a.point_side, a.p, c, d, v, a.sources);
}
inline Fundamental onPlane(const Fundamental& a, const Vector3d& c, const Vector3d& n) {
  return Fundamental::pointPlane(a.point_side, a.p, c, n, 0.0, a.sources);
}
// Angle between a vector of the point side (u_a) and one of the other side (u_b).
inline Fundamental angleAB(Side point_side, const Vector3d& u_a, const Vector3d& u_b, double v) {
  return point_side == Side::kMobile ? Fundamental::angle(u_a, u_b, v, 0)
                                     : Fundamental::angle(u_b, u_a, v, 0);
}

inline void one(RuleOutput& out, const Fundamental& f) { out.addAlternative().push_back(f); }
inline void two(RuleOutput& out, const Fundamental& f, const Fundamental& g) {
  Alt& a = out.addAlternative();
  a.push_back(f);
  a.push_back(g);
}
inline void three(RuleOutput& out, const Fundamental& f, const Fundamental& g,
                  const Fundamental& h) {
  Alt& a = out.addAlternative();
  a.push_back(f);
  a.push_back(g);
  a.push_back(h);
}

// --- the uncertainty of derived angle constraints (Fundamental::err) ---------------------------

// The direction along a span `len` long whose two ends are each known to the length tolerance.
inline double spanErr(double len, const Tolerance& tol) { return 2.0 * tol.length / len; }

// How far acos (asin) can move while its argument c is only known to ±dc: an angle read off a
// cosine near ±1 is known only to about sqrt(2 dc).
inline double acosSpread(double c, double dc) {
  const double a = std::acos(clampUnit(c));
  return std::max(std::abs(std::acos(clampUnit(c - dc)) - a),
                  std::abs(std::acos(clampUnit(c + dc)) - a));
}
inline double asinSpread(double s, double ds) {
  const double a = std::asin(clampUnit(s));
  return std::max(std::abs(std::asin(clampUnit(s - ds)) - a),
                  std::abs(std::asin(clampUnit(s + ds)) - a));
}

// The err of ∠ = acos(h / len) for a height h and a span len (> 0), both lengths known to the
// tolerance, the span's direction being one of the angle's vectors.
inline double heightAngleErr(double h, double len, const Tolerance& tol) {
  const double c = h / len;
  return acosSpread(c, tol.length * (1.0 + std::abs(c)) / len) + spanErr(len, tol);
}

inline Fundamental withErr(Fundamental f, double err) {
  f.err = err;
  return f;
}

// A rule of two translational constraints that decides its lengths within what their derivation
// leaves uncertain (Fundamental::err, in lengths) besides the tolerance.
// (F: the rule without the context, which no built-in rule reads.)
using RuleBody = void (*)(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                          RuleOutput& out);
template <RuleBody F>
void withLengthErr(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out, const void* /*context*/) {
  F(a, b, a.err + b.err > 0.0 ? tol.widenedLength(a.err + b.err) : tol, out);
}

// acos of a ratio that must lie in [-1, 1] up to tolerance; false when it does not.
inline bool acosChecked(double num, double den, double tol, double* angle) {
  double c = num / den;
  if (std::abs(num) > den + tol) return false;
  *angle = std::acos(c > 1 ? 1 : (c < -1 ? -1 : c));
  return true;
}

// Both constraints have their points on the same object (PMF's "a"), the other elements on "b".
inline bool sameRoles(const Fundamental& a, const Fundamental& b) {
  return a.point_side == b.point_side;
}
// Whether the two constraints constrain the same point of the same object (within the length
// tolerance), the guard of every rule on one point's two loci.
inline bool onePoint(const Fundamental& a, const Fundamental& b, const Tolerance& tol) {
  return sameRoles(a, b) && !((a.p - b.p).norm() > tol.length);
}

// Up to two points of line (c, d) at distance r from point x: c' ± k d with c' the foot of x.
// Returns how many (0, 1, 2); tangency within the length tolerance gives 1.
// How far k = sqrt(K) may be off when K is known to ±2 `spread`: spread / k, or sqrt(2 spread)
// where k is small (a tangency: K near 0; k = 0 gives that).
inline double rootErr(double spread, double k) {
  return std::min(spread / k, std::sqrt(2.0 * spread));
}

// `*err`: how far the points may be along the line with h and r known to the tolerance δ:
// (r + h) δ / k, or sqrt(2 (r + h) δ) where the line barely reaches into the sphere.
inline int lineSphere(const Vector3d& c, const Vector3d& d, const Vector3d& x, double r,
                      const Tolerance& tol, Vector3d out[2], double* err) {
  const Vector3d foot = projectOnLine(x, c, d);
  const double h = (x - foot).norm();
  if (h > r + tol.length) return 0;
  const double spread = (r + h) * tol.length;
  if (std::abs(h - r) <= tol.length) {
    out[0] = foot;
    *err = rootErr(spread, 0.0);
    return 1;
  }
  const double k = std::sqrt(r * r - h * h);
  *err = rootErr(spread, k);
  out[0] = foot + k * d;
  out[1] = foot - k * d;
  return 2;
}

}  // namespace relpos::rules::detail
