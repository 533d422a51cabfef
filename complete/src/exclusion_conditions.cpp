#include "exclusion_conditions.hpp"

#include <algorithm>
#include <cmath>

namespace relpos::complete::detail {
namespace {

double squareOf(double x) { return x * x; }

// The rounding of the normalised data (a few operations on numbers ~1): every range is widened
// by at least this much besides the tolerances.
constexpr double kRounding = 1e-12;

// What two conditions on the mobile object's points imply for its rotation alone, the
// translation eliminated (x₁ − x₂ = R (p₁ − p₂)), as an angle condition (R u)·d ∈ [lo, hi]
// (false: nothing): two offsets from planes of the same normal, two reaches, a reach and an
// offset. Each side of a conflict may be loose alone and the pair tight over every rotation;
// this one condition then excludes every box at once, where the two apart need boxes as small
// as the conflict's margin all over the rotations.
bool rotationPart(const Condition& a, const Condition& b, Condition* out) {
  using K = ConditionKind;
  const Vector3d v = vec(a.p) - vec(b.p), w = vec(a.q) - vec(b.q);
  Condition r;
  r.kind = K::kCosine;
  r.source = a.source;
  if (a.kind == K::kPointPlane && b.kind == K::kPointPlane) {
    const Vector3d d = vec(a.d);
    const double sign = vec(b.d) == d ? 1.0 : vec(b.d) == -d ? -1.0 : 0.0;
    if (sign == 0.0) return false;
    // (x_a − q_a)·d − (x_b − q_b)·d = (R v)·d − w·d
    const double blo = sign > 0.0 ? b.lo : -b.hi, bhi = sign > 0.0 ? b.hi : -b.lo;
    r.u = {v[0], v[1], v[2]}, r.d = a.d;
    r.lo = a.lo - bhi + w.dot(d), r.hi = a.hi - blo + w.dot(d);
  } else if (a.kind == K::kPointPoint && b.kind == K::kPointPoint) {
    if (!std::isfinite(a.hi) || !std::isfinite(b.hi)) return false;
    // |R v − w| ≤ r_a + r_b: |v|² − 2 (R v)·w + |w|² ≤ (r_a + r_b)²
    const double reach = std::sqrt(std::max(a.hi, 0.0)) + std::sqrt(std::max(b.hi, 0.0));
    r.u = {v[0], v[1], v[2]}, r.d = {w[0], w[1], w[2]};
    r.lo = 0.5 * (v.squaredNorm() + w.squaredNorm() - reach * reach), r.hi = kInf;
  } else if (a.kind == K::kPointPoint && b.kind == K::kPointPlane) {
    if (!std::isfinite(a.hi)) return false;
    // (x_b − q_b)·d = (x_a − q_a)·d − (R v)·d + w·d, |(x_a − q_a)·d| ≤ r_a
    const Vector3d d = vec(b.d);
    const double reach = std::sqrt(std::max(a.hi, 0.0)) * d.norm();
    r.u = {v[0], v[1], v[2]}, r.d = b.d;
    r.lo = w.dot(d) - b.hi - reach, r.hi = w.dot(d) - b.lo + reach;
  } else {
    return false;
  }
  // the rounding of the sums above, far over
  const double eps = 1e-12 * (1.0 + v.squaredNorm() + w.squaredNorm() +
                              std::abs(std::isfinite(r.lo) ? r.lo : 0.0) +
                              std::abs(std::isfinite(r.hi) ? r.hi : 0.0));
  r.lo -= eps, r.hi += eps;
  if (!(r.lo > -kInf) && !(r.hi < kInf)) return false;
  *out = r;
  return true;
}

}  // namespace

// The condition with its range widened by the tolerances, so that a pose meeting the constraint
// within them meets it (into `out`; an "a skew distance exactly d" becomes its two sides, a side
// that bounds nothing once widened is dropped).
void widen(const Condition& c, double tl, double ta, std::vector<Condition>* out) {
  Condition w = c;
  const double eps = kRounding * (1.0 + std::max(std::abs(std::isfinite(c.lo) ? c.lo : 0.0),
                                                 std::abs(std::isfinite(c.hi) ? c.hi : 0.0)));
  switch (c.kind) {
    case ConditionKind::kPointPoint:
    case ConditionKind::kPointLine:
    case ConditionKind::kLinePoint: {  // squared distances
      const double lo = c.lo > 0.0 ? std::sqrt(c.lo) - tl : -kInf;
      w.lo = lo > 0.0 ? squareOf(lo) - eps : -kInf;
      w.hi = std::isfinite(c.hi) ? squareOf(std::sqrt(std::max(c.hi, 0.0)) + tl) + eps : kInf;
      break;
    }
    case ConditionKind::kPointPlane:
    case ConditionKind::kPlanePoint:
    case ConditionKind::kSkew:  // |(x − q)·n| ≤ the distance as |n| ≤ 1
      w.lo = c.lo - tl - eps;
      w.hi = c.hi + tl + eps;
      break;
    case ConditionKind::kCosine:  // a cosine moves no more than its angle
      w.lo = c.lo - ta - eps;
      w.hi = c.hi + ta + eps;
      break;
    case ConditionKind::kSkewSquared: {
      // h² − k|n|² ≥ 0 (the distance at least √k) or ≤ 0 (at most): k moved with the distance
      const double d = std::sqrt(std::max(c.k, 0.0));
      if (c.hi > 0.0 || c.lo == c.hi) {  // at least d (exactly d: both sides)
        if (d - tl > 0.0) {
          Condition at_least = c;
          at_least.lo = 0.0, at_least.hi = kInf;
          at_least.k = squareOf(d - tl) * (1.0 - kRounding);
          out->push_back(at_least);
        }
      }
      if (c.lo < 0.0 || c.lo == c.hi) {
        Condition at_most = c;
        at_most.lo = -kInf, at_most.hi = 0.0;
        at_most.k = squareOf(d + tl) * (1.0 + kRounding) + kRounding;
        out->push_back(at_most);
      }
      return;
    }
  }
  out->push_back(w);
}

// A point on a point (three offsets along the axes, pose_conditions.cpp) is also a reach of
// at most the offsets' diagonal: added, so that it pairs with another reach (rotationPart).
void addImpliedReaches(std::vector<Condition>* cs) {
  const std::size_t n = cs->size();
  for (std::size_t i = 0; i < n; ++i) {
    const Condition& c = (*cs)[i];
    if (c.kind != ConditionKind::kPointPlane || vec(c.d) != Vector3d::UnitX()) continue;
    double r2 = squareOf(std::max(std::abs(c.lo), std::abs(c.hi)));
    int axes = 1;  // bit k: the offset along axis k is in
    for (std::size_t j = 0; j < n; ++j) {
      const Condition& e = (*cs)[j];
      if (e.kind != ConditionKind::kPointPlane || e.source != c.source || e.p != c.p || e.q != c.q)
        continue;
      for (int k = 1; k < 3; ++k)
        if (vec(e.d) == Vector3d::Unit(k) && !(axes & (1 << k))) {
          r2 += squareOf(std::max(std::abs(e.lo), std::abs(e.hi)));
          axes |= 1 << k;
        }
    }
    if (axes != 7 || !std::isfinite(r2)) continue;
    Condition ball = c;
    ball.kind = ConditionKind::kPointPoint;
    ball.d = {0.0, 0.0, 0.0};
    ball.lo = -kInf, ball.hi = r2 * (1.0 + 1e-12) + 1e-300;
    cs->push_back(ball);
  }
}

// When every condition is an angle of one mobile direction u (or −u): replaces u by z (−u by
// −z) and returns true. The conditions read the pose only through w = R u, and w ranges over
// the sphere of radius |u| = 1 (within rounding, which the ranges' widening covers) whatever u
// is: over all rotations, R z reaches the same values. Every direction R z is R' z for a
// rotation R' whose quaternion has no z part (R' = R Rz(φ) for the φ that zeroes it): the
// rotation search is 2-D. (Not a rotation M turning u onto z: one built in floating point is
// not orthogonal enough where u is near −z, and the search would miss directions.)
bool turnedOntoZ(std::vector<Condition>* cs) {
  if (cs->empty()) return false;
  const Vector3d u = vec(cs->front().u);
  for (const Condition& c : *cs)
    if (c.kind != ConditionKind::kCosine || (vec(c.u) != u && vec(c.u) != -u)) return false;
  for (Condition& c : *cs) c.u = {0.0, 0.0, vec(c.u) == u ? 1.0 : -1.0};
  return true;
}

// The conditions (their sources), and what each pair implies for the rotation alone.
void withRotationParts(const std::vector<Condition>& cs, std::vector<Condition>* out,
                       std::vector<SourceMask>* sources) {
  *out = cs;
  sources->clear();
  for (const Condition& c : cs) sources->push_back(sourceBit(c.source));
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (std::size_t j = 0; j < cs.size(); ++j) {
      Condition r;
      if (i == j || (cs[i].kind == cs[j].kind && j < i) || !rotationPart(cs[i], cs[j], &r))
        continue;
      out->push_back(r);
      sources->push_back(sourceBit(cs[i].source) | sourceBit(cs[j].source));
    }
}

}  // namespace relpos::complete::detail
