#include "set_exclusion.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "exclusion_conditions.hpp"
#include "exclusion_domain.hpp"
#include "rounded_interval.hpp"

namespace relpos::complete::detail {
namespace {

// A box narrower than this in every coordinate that no condition excludes: a pose of the
// widened conditions, or too near one to tell; nothing is proven.
constexpr double kSmallest = 1e-9;
// A contraction that keeps more than this fraction of a coordinate is not worth recording.
constexpr double kWorthwhile = 0.9;

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
      if (active & sourceBit(c.source))
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
    for (const Slab& sl : slabs) r.used |= sourceBit(sl.source);
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
