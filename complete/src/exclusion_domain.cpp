#include "exclusion_domain.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace relpos::complete::detail {

// The slabs the conditions give the translation t (x = R p + t, |R p| = |p|).
std::vector<Slab> translationSlabs(const std::vector<Condition>& cs) {
  std::vector<Slab> slabs;
  for (const Condition& c : cs) {
    const Vector3d p = vec(c.p), q = vec(c.q), d = vec(c.d);
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

}  // namespace relpos::complete::detail
