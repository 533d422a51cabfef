#include "set_exclusion.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "rounded_interval.hpp"
#include "translation_bound.hpp"

namespace relpos::complete::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The rounding of the normalised data (a few operations on numbers ~1): every range is widened
// by at least this much besides the tolerances.
constexpr double kRounding = 1e-12;
// A box narrower than this in every coordinate that no condition excludes: a pose of the
// widened conditions, or too near one to tell; nothing is proven.
constexpr double kSmallest = 1e-9;
// A contraction that keeps more than this fraction of a coordinate is not worth recording.
constexpr double kWorthwhile = 0.9;

SourceMask bit(int source) { return SourceMask{1} << (source % 64); }

double squareOf(double x) { return x * x; }

Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

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

// The slabs the conditions give the translation t (x = R p + t, |R p| = |p|).
std::vector<Slab> translationSlabs(const std::vector<Condition>& cs) {
  std::vector<Slab> slabs;
  for (const Condition& c : cs) {
    const Vector3d p(c.p[0], c.p[1], c.p[2]), q(c.q[0], c.q[1], c.q[2]), d(c.d[0], c.d[1], c.d[2]);
    if (c.kind == ConditionKind::kPointPoint && std::isfinite(c.hi)) {
      ballSlabs(q, p.norm() + std::sqrt(std::max(c.hi, 0.0)), &slabs, c.source);
    } else if (c.kind == ConditionKind::kPointPlane && std::isfinite(c.lo) && std::isfinite(c.hi)) {
      slabs.push_back({d, c.lo + d.dot(q) - p.norm(), c.hi + d.dot(q) + p.norm(), c.source});
    } else if (c.kind == ConditionKind::kPointLine && std::isfinite(c.hi)) {
      const double reach = p.norm() + std::sqrt(std::max(c.hi, 0.0));
      const Vector3d n1 = d.unitOrthogonal(), n2 = d.cross(n1);
      for (const Vector3d& n : {n1, n2})
        slabs.push_back({n, n.dot(q) - reach, n.dot(q) + reach, c.source});
    }
  }
  return slabs;
}

// A world frame whose axes follow the conditions' fixed directions (planes' normals first): a
// slab across an axis then bounds one coordinate of a box, not a sum of three.
Matrix3d alignedFrame(const std::vector<Condition>& cs) {
  std::vector<Vector3d> axes;
  auto offer = [&](const std::array<double, 3>& a) {
    if (axes.size() >= 2) return;
    Vector3d v(a[0], a[1], a[2]);
    if (!(v.norm() > 0.0)) return;
    v.normalize();
    for (const Vector3d& e : axes) v -= v.dot(e) * e;
    if (v.norm() > 0.3) axes.push_back(v.normalized());
  };
  for (const Condition& c : cs)
    if (c.kind == ConditionKind::kPointPlane) offer(c.d);
  // two reaches from different fixed points: the line between them, along which they part
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (std::size_t j = i + 1; j < cs.size(); ++j)
      if (cs[i].kind == ConditionKind::kPointPoint && cs[j].kind == ConditionKind::kPointPoint) {
        const std::array<double, 3>& a = cs[i].q;
        const std::array<double, 3>& b = cs[j].q;
        offer({a[0] - b[0], a[1] - b[1], a[2] - b[2]});
      }
  for (ConditionKind k : {ConditionKind::kPointLine, ConditionKind::kCosine, ConditionKind::kSkew})
    for (const Condition& c : cs)
      if (c.kind == k) offer(c.d);
  for (int i = 0; i < 3; ++i) offer({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
  Matrix3d F;
  F.col(2) = axes[0];
  F.col(0) = axes[1];
  F.col(1) = F.col(2).cross(F.col(0));
  return F;
}

// Whether no condition depends on the translation's coordinate i: exactly (a zero in the data,
// so that the interval evaluation multiplies it by an exact zero), as a plane across another
// axis, a line along this one, a cosine.
bool independentOf(const std::vector<Condition>& cs, int i) {
  auto along = [i](const std::array<double, 3>& d) {
    for (int j = 0; j < 3; ++j)
      if (j != i && d[j] != 0.0) return false;
    return true;
  };
  for (const Condition& c : cs) {
    switch (c.kind) {
      case ConditionKind::kCosine:
        break;
      case ConditionKind::kPointPlane:
        if (c.d[i] != 0.0) return false;
        break;
      case ConditionKind::kPointLine:
      case ConditionKind::kSkew:
      case ConditionKind::kSkewSquared:  // the common normal is across d
        if (!along(c.d)) return false;
        break;
      default:
        return false;
    }
  }
  return true;
}

using Box = std::array<FI, 6>;

struct Node {
  Box y;
  SourceMask used = 0;  // the constraints that contracted it or its ancestors
  int chart = 0;        // chartBase(chart)
};

FI allowedRange(const Condition& c) {
  // a huge finite bound for an open side: no ∞ − ∞ in the contraction
  return FI(std::isfinite(c.lo) ? c.lo : -1e300, std::isfinite(c.hi) ? c.hi : 1e300);
}

// An upper bound on |u| |d| (a rotation keeps lengths): rounded up far beyond the rounding.
double rotatedReach(const Condition& c) {
  return vec(c.u).norm() * vec(c.d).norm() * (1.0 + 1e-12) + 1e-300;
}

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

// The conditions (their sources), and what each pair implies for the rotation alone.
void withRotationParts(const std::vector<Condition>& cs, std::vector<Condition>* out,
                       std::vector<SourceMask>* sources) {
  *out = cs;
  sources->clear();
  for (const Condition& c : cs) sources->push_back(bit(c.source));
  for (std::size_t i = 0; i < cs.size(); ++i)
    for (std::size_t j = 0; j < cs.size(); ++j) {
      Condition r;
      if (i == j || (cs[i].kind == cs[j].kind && j < i) || !rotationPart(cs[i], cs[j], &r))
        continue;
      out->push_back(r);
      sources->push_back(bit(cs[i].source) | bit(cs[j].source));
    }
}

// One quaternion chart of the search: the conditions in its base's frame, and W mapping the
// node's translation coordinates τ to the translation in that frame (W = R0ᵀ T).
struct ChartOfSearch {
  std::vector<Condition> conditions;
  std::vector<SourceMask> sources;  // per condition: the constraints it follows from
  Matrix3d W;
};

// The pose coordinates (a, b, c, W τ) of box coordinates y = (a, b, c, τ).
template <typename T>
std::array<T, 6> poseCoordinates(const std::array<T, 6>& y, const Matrix3d& W) {
  std::array<T, 6> z = y;
  for (int i = 0; i < 3; ++i) {
    z[3 + i] = y[3] * W(i, 0);
    z[3 + i] = z[3 + i] + y[4] * W(i, 1);
    z[3 + i] = z[3 + i] + y[5] * W(i, 2);
  }
  return z;
}

// Evaluates every condition over the node's box; contracts it. Returns the constraints of a
// condition that excludes the box, or 0.
SourceMask pruneOrContract(const ChartOfSearch& chart, Node* node) {
  Box& y = node->y;
  std::array<Dual<FI>, 6> yd;
  Box mid;
  for (int i = 0; i < 6; ++i) {
    yd[i] = Dual<FI>::variable(y[i], i);
    mid[i] = FI(midpoint(y[i]));
  }
  const LocalPose<Dual<FI>> X(poseCoordinates(yd, chart.W));
  const LocalPose<FI> Xm(poseCoordinates(mid, chart.W));
  for (std::size_t k = 0; k < chart.conditions.size(); ++k) {
    const Condition& c = chart.conditions[k];
    const SourceMask source = chart.sources[k];
    const Dual<FI> g = evaluate(c, X);
    const FI gm = evaluate(c, Xm);
    std::array<FI, 6> offset;  // G_j (y_j − m_j)
    FI mv = gm;
    for (int j = 0; j < 6; ++j) {
      offset[j] = g.g[j] * (y[j] - mid[j]);
      mv += offset[j];
    }
    double lo = std::max(g.v.lower(), mv.lower()), hi = std::min(g.v.upper(), mv.upper());
    if (c.kind == ConditionKind::kCosine) {  // |(R u)·d| ≤ |u| |d|, whatever the box
      const double reach = rotatedReach(c);
      lo = std::max(lo, -reach), hi = std::min(hi, reach);
    }
    if (hi < c.lo || lo > c.hi) return source;
    // y_j within m_j + (range − g(m) − Σ_{i≠j} G_i (y_i − m_i)) / G_j
    const FI allowed = allowedRange(c);
    for (int j = 0; j < 6; ++j) {
      if (!(g.g[j].lower() > 0.0 || g.g[j].upper() < 0.0)) continue;
      FI rest = gm;
      for (int i = 0; i < 6; ++i)
        if (i != j) rest += offset[i];
      const FI yj = mid[j] + (allowed - rest) / g.g[j];
      const double a = std::max(y[j].lower(), yj.lower()), b = std::min(y[j].upper(), yj.upper());
      if (!(a <= b)) {
        if (std::isnan(a) || std::isnan(b)) continue;
        return source;
      }
      if (b - a < kWorthwhile * width(y[j])) {
        y[j] = FI(a, b);
        node->used |= source;
      }
    }
  }
  return 0;
}

// When every condition that reads the translation is a plane offset, along at most two
// directions (the same vector or its negation — a plane's normal, placed once): they read t only
// through t·d₁, t·d₂, so the translations T τ = τ₀ d₁ + τ₁ d₂ (the projection of any t on their
// span, with the same offsets) hold every solution's. The slabs bound τ through the Gram matrix.
// kUnbounded when the conditions are not of that shape.
Bound planesOnly(const std::vector<Condition>& cs, const std::vector<Slab>& slabs, Matrix3d* T,
                 Vector3d* lo, Vector3d* hi) {
  std::vector<Vector3d> dirs;
  auto same = [](const Vector3d& a, const Vector3d& b) { return a == b || a == -b; };
  for (const Condition& c : cs) {
    if (c.kind == ConditionKind::kCosine) continue;
    if (c.kind != ConditionKind::kPointPlane) return Bound::kUnbounded;
    const Vector3d d(c.d[0], c.d[1], c.d[2]);
    bool known = false;
    for (const Vector3d& e : dirs) known = known || same(d, e);
    if (!known) dirs.push_back(d);
  }
  if (dirs.empty() || dirs.size() > 2) return Bound::kUnbounded;
  // the offsets' bounds s_k ∈ [slo_k, shi_k] along each direction (a negated normal: negated)
  const int k = static_cast<int>(dirs.size());
  double slo[2] = {-kInf, -kInf}, shi[2] = {kInf, kInf};
  for (const Slab& sl : slabs)
    for (int j = 0; j < k; ++j) {
      if (sl.n == dirs[j]) slo[j] = std::max(slo[j], sl.lo), shi[j] = std::min(shi[j], sl.hi);
      if (sl.n == -dirs[j]) slo[j] = std::max(slo[j], -sl.hi), shi[j] = std::min(shi[j], -sl.lo);
    }
  for (int j = 0; j < k; ++j) {
    if (!std::isfinite(slo[j]) || !std::isfinite(shi[j])) return Bound::kUnbounded;
    if (slo[j] > shi[j]) return Bound::kEmpty;
  }
  Eigen::Matrix2d G = Eigen::Matrix2d::Identity();
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) G(a, b) = dirs[a].dot(dirs[b]);
  if (!(G.determinant() > 1e-3)) return Bound::kUnbounded;  // nearly parallel: too wide a box
  const Eigen::Matrix2d inv = G.inverse();
  T->setZero();
  *lo = Vector3d::Zero(), *hi = Vector3d::Zero();
  for (int a = 0; a < k; ++a) {
    T->col(a) = dirs[a];
    double low = 0.0, high = 0.0;
    for (int b = 0; b < k; ++b) {
      const double x = inv(a, b) * slo[b], y = inv(a, b) * shi[b];
      low += std::min(x, y), high += std::max(x, y);
    }
    // far more than the rounding of G⁻¹
    const double slack = 1e-6 * (1.0 + std::abs(low) + std::abs(high));
    (*lo)[a] = low - slack, (*hi)[a] = high + slack;
  }
  return Bound::kBox;
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

// The four quaternion charts' bases: the identity and the half turns about x, y, z.
Matrix3d chartBase(int k) {
  Vector3d s(1.0, 1.0, 1.0);
  if (k > 0) s = -s, s[k - 1] = 1.0;
  return s.asDiagonal();
}

}  // namespace

PoseExclusion excludeEveryPose(const ConditionSystem& system, SourceMask active,
                               const ExcludeOptions& options) {
  PoseExclusion r;
  std::vector<Condition> widened;
  for (const auto* list : {&system.equations, &system.inequalities})
    for (const Condition& c : *list)
      if (active & bit(c.source))
        widen(c, options.length_tolerance, options.angle_tolerance, &widened);
  addImpliedReaches(&widened);
  const Matrix3d F = alignedFrame(widened);
  std::vector<Condition> world;  // in the aligned frame
  inBaseFrame(widened, F, Vector3d::Zero(), &world);
  bool moves = false;  // whether any condition depends on the translation
  for (const Condition& c : world) moves = moves || c.kind != ConditionKind::kCosine;
  // the translation t = T τ, τ in [tlo, thi]
  Matrix3d T = Matrix3d::Identity();
  Vector3d tlo = Vector3d::Zero(), thi = Vector3d::Zero();
  if (moves) {
    const std::vector<Slab> slabs = translationSlabs(world);
    for (const Slab& sl : slabs) r.used |= bit(sl.source);
    Bound b = boundingBox(slabs, 0.0, &tlo, &thi);
    if (b == Bound::kUnbounded) b = planesOnly(world, slabs, &T, &tlo, &thi);
    if (b == Bound::kEmpty) {
      r.proven = true;
      return r;
    }
    for (int i = 0; i < 3; ++i) {
      if (b != Bound::kUnbounded || (std::isfinite(tlo[i]) && std::isfinite(thi[i]))) continue;
      if (!independentOf(world, i)) {
        r.used = 0;
        r.unbounded = true;
        r.why = "the constraints do not bound the position";
        return r;
      }
      tlo[i] = thi[i] = 0.0;  // no condition reads it: any value will do
    }
  }
  // Angles of one mobile direction alone: the spin about it changes nothing, so the rotations
  // with no z part of their quaternion suffice once that direction is turned onto z.
  const bool spin_free = turnedOntoZ(&world);
  std::vector<Condition> derived;
  std::vector<SourceMask> derived_sources;
  withRotationParts(world, &derived, &derived_sources);
  RoundUp rounding;
  std::vector<Node> stack;
  std::vector<ChartOfSearch> charts(4);
  for (int k = spin_free ? 2 : 3; k >= 0; --k) {  // the identity's chart first
    const Matrix3d R0 = chartBase(k);
    inBaseFrame(derived, R0, Vector3d::Zero(), &charts[k].conditions);
    charts[k].sources = derived_sources;
    charts[k].W = R0.transpose() * T;  // exact: R0 is diagonal, ±1
    Node n;
    for (int i = 0; i < 3; ++i) {
      n.y[i] = FI(-1.0, 1.0);
      n.y[3 + i] = FI(tlo[i], thi[i]);
    }
    // the coordinate that is the quaternion's z part in this chart (e_k ⊗ (1, a, b, c))
    if (spin_free) n.y[k == 0 ? 2 : k == 1 ? 1 : 0] = FI(0.0);
    n.chart = k;
    stack.push_back(n);
  }
  while (!stack.empty()) {
    if (r.boxes >= options.max_boxes) {
      r.used = 0;
      r.why = "not every pose excluded after " + std::to_string(r.boxes) + " boxes";
      return r;
    }
    ++r.boxes;
    Node node = stack.back();
    stack.pop_back();
    const SourceMask source = pruneOrContract(charts[node.chart], &node);
    if (source != 0) {
      r.used |= node.used | source;
      continue;
    }
    int j = 0;
    for (int i = 1; i < 6; ++i)
      if (width(node.y[i]) > width(node.y[j])) j = i;
    if (width(node.y[j]) < kSmallest) {
      r.used = 0;
      r.why = "a pose meets the constraints within their tolerances, or too nearly to tell";
      return r;
    }
    Node a = node, b = node;
    std::tie(a.y[j], b.y[j]) = halves(node.y[j]);
    stack.push_back(b);
    stack.push_back(a);
  }
  r.proven = true;
  return r;
}

}  // namespace relpos::complete::detail
