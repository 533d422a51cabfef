#include "dependent_equations.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "chart.hpp"
#include "implied_equations.hpp"

namespace relpos::complete::detail {
namespace {

// A cosine this small is a right angle's (cos(π/2) rounds to 6e-17): its row holds the direction
// across its normal to within this times the reach, far below any tolerance.
constexpr double kZeroCosine = 1e-15;

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Directions at least this far apart (the sine of their angle) give orthonormal bases and cross
// products whose rounding stays far under kInSpan's gap; lines this far from parallel are apart.
constexpr double kApart = 0.1;

// Greedy rank selection: whether v adds a direction to `basis` (orthonormal, extended by it
// when it does): its part off their span above `gap` of its length.
bool extendsSpan(const Vector3d& v, double gap, std::vector<Vector3d>* basis) {
  Vector3d r = v;
  for (const Vector3d& e : *basis) r -= r.dot(e) * e;
  if (!(r.norm() > gap * v.norm())) return false;
  basis->push_back(r.normalized());
  return true;
}

// A vector within this of a span (relative to its length) is in it: the structure of the
// decompositions (the same vectors, their cross products), not a coincidence of the pose.
bool inSpan(const Vector3d& v, const std::vector<Vector3d>& basis) {
  Vector3d r = v;
  for (const Vector3d& e : basis) r -= r.dot(e) * e;
  return r.norm() <= kInSpan * v.norm();
}

// What the kept equations hold constant on any connected piece of their set through the base.
struct Pinned {
  Matrix3d R0 = Matrix3d::Identity();    // the base's rotation (signs of world directions)
  bool rotation = false;                 // the angles' rank is 3 in the rotation's coordinates
  std::vector<Vector3d> slides;          // with the rotation pinned: every plane row's normal
  std::vector<std::array<double, 3>> u;  // per mobile direction: its (orthonormal) rows...
  std::vector<std::vector<Vector3d>> rows, zero_rows;  // ...and those of value 0
  std::vector<std::array<double, 3>> p;                // per mobile point: its plane rows' normals
  std::vector<std::vector<Vector3d>> normals;

  // The index of direction k (or one parallel to it) among `keys`, of point k with `point`;
  // −1: none.
  static int find(const std::vector<std::array<double, 3>>& keys, const std::array<double, 3>& k,
                  bool point = false) {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == k || (!point && vec(k).norm() > 0.0 &&
                           vec(keys[i]).cross(vec(k)).norm() <=
                               kInSpan * vec(keys[i]).norm() * vec(k).norm()))
        return static_cast<int>(i);
    return -1;
  }
  // A direction is pinned by two independent angle rows (then finitely many directions meet
  // them) or by a pinned rotation.
  bool direction(const std::array<double, 3>& d) const {
    const int i = find(u, d);
    return rotation || (i >= 0 && rows[static_cast<std::size_t>(i)].size() >= 2);
  }
  // The world direction R d of mobile direction d (unit) when two right angles pin it, to the
  // rounding of the fixed data (their normals' cross product, its sign the base's); false
  // otherwise.
  bool world(const std::array<double, 3>& d, Vector3d* w) const {
    const int i = find(u, d);
    if (i < 0 || zero_rows[static_cast<std::size_t>(i)].size() != 2) return false;
    const std::vector<Vector3d>& z = zero_rows[static_cast<std::size_t>(i)];
    *w = z[0].cross(z[1]).normalized();
    if (w->dot(R0 * vec(d)) < 0.0) *w = -*w;
    return true;
  }
  // Point q's coordinate along normal n is held (and every point's, with the rotation pinned).
  // (Spans of held normals grow only by normals far from them, kApart: their orthonormal bases
  // then round far under kInSpan, and a normal in a span is never counted as a new one.)
  void hold(const std::array<double, 3>& q, const Vector3d& n) {
    extendsSpan(n, kApart, &slides);
    int k = find(p, q, true);
    if (k < 0) {
      k = static_cast<int>(p.size());
      p.push_back(q), normals.emplace_back();
    }
    extendsSpan(n, kApart, &normals[static_cast<std::size_t>(k)]);
  }
  // Whether point q moves with point r: the same, or differing along a pinned direction
  // (x_q − x_r = R (q − r) is pinned): q's coordinates along r's held normals are held too (a
  // plane offset folds its value into the plane's point, pose_conditions.cpp: the same plane,
  // another point on its normal).
  bool movesWith(const std::array<double, 3>& q, const std::array<double, 3>& r) const {
    if (q == r) return true;
    const Vector3d step = vec(q) - vec(r);
    for (std::size_t k = 0; k < u.size(); ++k)
      if (rows[k].size() >= 2 &&
          step.cross(vec(u[k])).norm() <= kInSpan * step.norm() * vec(u[k]).norm())
        return true;
    return false;
  }
  // The span of point q's coordinates held constant: the held normals of the points it moves
  // with (every one with the rotation pinned: x = R p + t).
  std::vector<Vector3d> held(const std::array<double, 3>& q) const {
    if (rotation) return slides;
    std::vector<Vector3d> span;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (movesWith(q, p[i]))
        for (const Vector3d& n : normals[i]) extendsSpan(n, kApart, &span);
    // Along the world direction w of a pinned direction v, any two points differ by a constant
    // ((R(q − p))·(R v) = (q − p)·v): w held for one point is held for every point.
    for (const std::array<double, 3>& v : u) {
      Vector3d w;
      if (!world(v, &w)) continue;
      for (const std::vector<Vector3d>& n : normals)
        if (inSpan(w, n)) {
          extendsSpan(w, kApart, &span);
          break;
        }
    }
    return span;
  }
  // Point q held across (along) the world direction w of pinned direction d: its held span
  // holds w's orthogonal plane (holds w).
  bool across(const std::array<double, 3>& d, const std::array<double, 3>& q) const {
    Vector3d w;
    if (!world(d, &w)) return false;
    const std::vector<Vector3d> h = held(q);
    const Vector3d e = w.unitOrthogonal();
    return inSpan(e, h) && inSpan(w.cross(e), h);
  }
  bool along(const std::array<double, 3>& d, const std::array<double, 3>& q) const {
    Vector3d w;
    return world(d, &w) && inSpan(w, held(q));
  }
};

// A skew condition whose mobile line turns in a plane across a pinned direction's world w and
// whose fixed line is across w too (`w`: that w): n = R u × d is along w, h = ±|n|·(x − q)·w,
// and where the lines are not parallel (n ≠ 0) it reads only the height (x − q)·w — their
// distance |h|/|n|. (Where they are parallel h and |n| vanish together, whatever the distance.)
bool skewAcross(const Condition& c, const Pinned& pinned, Vector3d* w) {
  if (c.kind != ConditionKind::kSkew && c.kind != ConditionKind::kSkewSquared) return false;
  for (const std::array<double, 3>& v : pinned.u)
    if (pinned.world(v, w) && std::abs(vec(c.u).dot(vec(v))) <= kInSpan * vec(c.u).norm() &&
        std::abs(vec(c.d).dot(*w)) <= kInSpan * vec(c.d).norm())
      return true;
  return false;
}

// Such a condition with its point held along w: a constant where the lines are not parallel.
bool skewAlongPinned(const Condition& c, const Pinned& pinned) {
  Vector3d w;
  return skewAcross(c, pinned, &w) && inSpan(w, pinned.held(c.p));
}

// Whether equation c is a constant on the piece where `pinned` holds.
// `guard`: set when that holds only where the lines c reads are not parallel (skewAlongPinned).
bool constantWhere(const Condition& c, const Pinned& pinned, bool* guard) {
  *guard = false;
  if (c.kind == ConditionKind::kCosine) return pinned.direction(c.u);
  const std::vector<Vector3d> h = pinned.held(c.p);
  const std::size_t held = h.size();
  switch (c.kind) {
    case ConditionKind::kPointPlane:
      return inSpan(vec(c.d), h);
    case ConditionKind::kPointPoint:
      return held == 3;
    case ConditionKind::kPointLine:  // reads x across the fixed line d (to 1e-13 of it)
      return held == 3 || (held == 2 && std::abs(h[0].dot(vec(c.d))) <= kInSpan &&
                           std::abs(h[1].dot(vec(c.d))) <= kInSpan);
    case ConditionKind::kLinePoint:  // reads w and x across w
      return pinned.direction(c.u) && (held == 3 || pinned.across(c.u, c.p));
    case ConditionKind::kPlanePoint:  // reads w and x along w
      return pinned.direction(c.u) && (held == 3 || pinned.along(c.u, c.p));
    case ConditionKind::kSkew:
    case ConditionKind::kSkewSquared:  // reads w and x along w × d, across w
      if (pinned.direction(c.u) && (held == 3 || pinned.across(c.u, c.p))) return true;
      *guard = skewAlongPinned(c, pinned);
      return *guard;
    default:
      return false;
  }
}

// Whether condition c reads its mobile point only across w, the world direction of mobile
// direction v (pinned).
bool readsAcross(const Condition& c, const std::array<double, 3>& v, const Vector3d& w) {
  const Vector3d d = vec(c.d);
  const bool along_v = vec(c.u).cross(vec(v)).norm() <= kInSpan * vec(c.u).norm() * vec(v).norm();
  switch (c.kind) {
    case ConditionKind::kPointPlane:
      return std::abs(d.dot(w)) <= kInSpan * d.norm();
    case ConditionKind::kPointLine:
      return d.cross(w).norm() <= kInSpan * d.norm();
    case ConditionKind::kLinePoint:
    case ConditionKind::kSkew:
    case ConditionKind::kSkewSquared:
      return along_v && vec(c.u).norm() > 0.0;
    default:
      return false;
  }
}

// Mobile direction d held to world w (up to sign): rows across w, of value 0.
void pinDirection(Pinned* pinned, const std::array<double, 3>& d, const Vector3d& w) {
  int k = Pinned::find(pinned->u, d);
  if (k < 0) {
    k = static_cast<int>(pinned->u.size());
    pinned->u.push_back(d), pinned->rows.emplace_back(), pinned->zero_rows.emplace_back();
  }
  const Vector3d e = w.unitOrthogonal();
  for (const Vector3d& n : {e, w.cross(e)}) {
    extendsSpan(n, kInSpan, &pinned->rows[static_cast<std::size_t>(k)]);
    extendsSpan(n, kInSpan, &pinned->zero_rows[static_cast<std::size_t>(k)]);
  }
}

// A mobile line through two fixed points (each a pair of zero offsets from planes through the
// line, pose_conditions.cpp): its direction held to theirs, `line` its mobile direction.
void pinLinesThroughTwoPoints(const ConditionSystem& system, const std::vector<bool>& keep,
                              Pinned* pinned) {
  struct Through {
    std::array<double, 3> p;
    Vector3d line, q;
  };
  std::vector<Through> through;  // each fixed point found on a mobile line
  const std::size_t n = keep.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const Condition& e = system.equations[a];
      const Condition& f = system.equations[b];
      if (!keep[a] || !keep[b] || e.kind != ConditionKind::kPlanePoint ||
          f.kind != ConditionKind::kPlanePoint || e.p != f.p || e.q != f.q || e.lo != 0.0 ||
          f.lo != 0.0)
        continue;
      const Vector3d line = vec(e.u).cross(vec(f.u));
      if (line.norm() < 0.5) continue;
      through.push_back({e.p, line.normalized(), vec(e.q)});
    }
  for (std::size_t a = 0; a < through.size(); ++a)
    for (std::size_t b = a + 1; b < through.size(); ++b) {
      const Through& s = through[a];
      const Through& t = through[b];
      const Vector3d step = t.q - s.q;
      if (s.p != t.p || s.line.cross(t.line).norm() > kInSpan || step.norm() == 0.0) continue;
      std::array<double, 3> line;
      for (int i = 0; i < 3; ++i) line[static_cast<std::size_t>(i)] = s.line[i];
      pinDirection(pinned, line, step.normalized());
    }
}

// What the equations kept (keep[i]) pin on their set through the base; `rows`: every
// equation's gradient there, R0 the base's rotation.
Pinned pinnedBy(const ConditionSystem& system, const std::vector<bool>& keep,
                const std::vector<Vector6d>& rows, const Matrix3d& R0) {
  Pinned pinned;
  pinned.R0 = R0;
  std::vector<Vector3d> turns;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const Condition& c = system.equations[i];
    if (!keep[i]) continue;
    if (c.kind == ConditionKind::kCosine) {
      extendsSpan(rows[i].head<3>(), kRankGap, &turns);
      int k = Pinned::find(pinned.u, c.u);
      if (k < 0) {
        k = static_cast<int>(pinned.u.size());
        pinned.u.push_back(c.u), pinned.rows.emplace_back(), pinned.zero_rows.emplace_back();
      }
      extendsSpan(vec(c.d), kInSpan, &pinned.rows[static_cast<std::size_t>(k)]);
      // a right angle's normal far from the earlier ones' span (kApart): their orthonormal
      // basis, and world()'s cross product of it, then round far under kInSpan
      if (std::abs(c.lo) <= kZeroCosine)
        extendsSpan(vec(c.d), kApart, &pinned.zero_rows[static_cast<std::size_t>(k)]);
    } else if (c.kind == ConditionKind::kPointPlane) {
      pinned.hold(c.p, vec(c.d));
    }
  }
  pinned.rotation = turns.size() >= 3;
  pinLinesThroughTwoPoints(system, keep, &pinned);
  // A fixed point's offset from a mobile plane whose normal two right angles pin (to world w):
  // the plane's point held along w. Two such offsets of 0 from planes through one mobile line
  // whose direction is so pinned (the fixed point on the line): the line's point held across it.
  std::vector<std::size_t> offsets;
  for (std::size_t i = 0; i < keep.size(); ++i)
    if (keep[i] && system.equations[i].kind == ConditionKind::kPlanePoint) offsets.push_back(i);
  for (std::size_t i : offsets) {
    const Condition& c = system.equations[i];
    Vector3d w;
    if (pinned.world(c.u, &w)) pinned.hold(c.p, w);
  }
  for (std::size_t a = 0; a < offsets.size(); ++a)
    for (std::size_t b = a + 1; b < offsets.size(); ++b) {
      const Condition& e = system.equations[offsets[a]];
      const Condition& f = system.equations[offsets[b]];
      if (e.p != f.p || e.q != f.q || e.lo != 0.0 || f.lo != 0.0) continue;
      const Vector3d axis = vec(e.u).cross(vec(f.u));
      for (const std::array<double, 3>& v : pinned.u) {
        Vector3d w;
        if (!pinned.world(v, &w) || !inSpan(axis, {vec(v).normalized()}) || axis.norm() < 0.5)
          continue;
        const Vector3d across = w.unitOrthogonal();
        pinned.hold(e.p, across);
        pinned.hold(e.p, w.cross(across));
      }
    }
  // Such a skew condition kept, its lines well apart at the base (n ≠ 0): on the piece the
  // lines cannot turn parallel — there the kept equations are singular (the squared form's
  // gradient vanishes; the plain one's set crosses the parallel poses' only where the height is
  // 0 too), which the chart's proof excludes — so it holds the height (x − q)·w at one of the
  // finitely many values it allows.
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const Condition& c = system.equations[i];
    Vector3d w;
    if (keep[i] && skewAcross(c, pinned, &w) &&
        (R0 * vec(c.u)).cross(vec(c.d)).norm() >= kApart * vec(c.u).norm() * vec(c.d).norm())
      pinned.hold(c.p, w);
  }
  // Two independent equations that read only where a point is across a pinned direction's world
  // w (an offset along a normal across w, a distance to a fixed line along w, a distance or skew
  // distance of a mobile line along w): that place is isolated, so held — the equations stay
  // independent over a chart (its proof), and so it is a constant on the chart's piece.
  for (const std::array<double, 3>& v : pinned.u) {
    Vector3d w;
    if (!pinned.world(v, &w)) continue;
    for (std::size_t i = 0; i < keep.size(); ++i) {
      if (!keep[i]) continue;
      int across = 0;
      for (std::size_t j = 0; j < keep.size(); ++j)
        across += keep[j] && pinned.movesWith(system.equations[j].p, system.equations[i].p) &&
                  readsAcross(system.equations[j], v, w);
      if (across < 2) continue;
      const Vector3d e = w.unitOrthogonal();
      pinned.hold(system.equations[i].p, e);
      pinned.hold(system.equations[i].p, w.cross(e));
    }
  }
  return pinned;
}

// Whether the equations not kept are constants where the kept ones hold (all of them when six
// are kept: their set is, near the base, the base alone — an overdetermined system's isolated
// pose).
// `guarded`: the conditions so dropped that hold only where their lines are not parallel.
bool droppedConstant(const ConditionSystem& system, const std::vector<bool>& keep,
                     const std::vector<Vector6d>& rows, const Matrix3d& R0,
                     std::vector<std::size_t>* guarded) {
  guarded->clear();
  if (std::count(keep.begin(), keep.end(), true) == 6) return true;
  const Pinned pinned = pinnedBy(system, keep, rows, R0);
  for (std::size_t i = 0; i < keep.size(); ++i) {
    bool guard = false;
    if (keep[i]) continue;
    if (!constantWhere(system.equations[i], pinned, &guard)) return false;
    if (guard) guarded->push_back(i);
  }
  return true;
}

// Whether the rows marked in `keep` are independent (each one's part off the earlier ones'
// span above the rank gap).
bool independent(const std::vector<Vector6d>& rows, const std::vector<bool>& keep) {
  std::vector<Vector6d> basis;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!keep[i]) continue;
    Vector6d r = rows[i];
    for (const Vector6d& e : basis) r -= r.dot(e) * e;
    if (!(r.norm() > kRankGap * std::max(1.0, rows[i].norm()))) return false;
    basis.push_back(r.normalized());
  }
  return true;
}

// The next choice of `count` of n indices to drop after `drop` (lexicographic); false after
// the last.
bool nextChoice(std::vector<std::size_t>* drop, std::size_t n) {
  const std::size_t k = drop->size();
  for (std::size_t i = k; i-- > 0;)
    if ((*drop)[i] < n - k + i) {
      ++(*drop)[i];
      for (std::size_t j = i + 1; j < k; ++j) (*drop)[j] = (*drop)[j - 1] + 1;
      return true;
    }
  return false;
}

// The most choices of which dependent equations to drop tried (C(8, 4) = 70, C(10, 5) = 252).
constexpr int kMostChoices = 256;

// Every equation's gradient in the coordinates about the base pose (R0, t0).
std::vector<Vector6d> gradientsAt(const ConditionSystem& system, const Matrix3d& R0,
                                  const Vector3d& t0) {
  std::array<Dual<double>, 6> y;
  for (int i = 0; i < 6; ++i) y[i] = Dual<double>::variable(0.0, i);
  const LocalPose<Dual<double>> X(y);
  std::vector<Vector6d> rows(system.equations.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Dual<double> g = evaluate(inBaseFrame(system.equations[i], R0, t0), X);
    for (int j = 0; j < 6; ++j) rows[i][j] = g.g[j];
  }
  return rows;
}

}  // namespace

bool reduceDependent(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0,
                     ConditionSystem* reduced, std::vector<Condition>* dropped) {
  dropped->clear();
  const std::size_t n = system.equations.size();
  const std::vector<Vector6d> rows = gradientsAt(system, R0, t0);
  // the equations independent at the base (greedily, in their canonical order): the linear
  // ones first — what pins directions and points — then the others, which read them
  std::vector<Vector6d> basis;
  std::vector<bool> keep(n, false);
  for (const bool linear_pass : {true, false})
    for (std::size_t i = 0; i < n; ++i) {
      if (linear(system.equations[i]) != linear_pass) continue;
      Vector6d r = rows[i];
      for (const auto& e : basis) r -= r.dot(e) * e;
      keep[i] = r.norm() > kRankGap * std::max(1.0, rows[i].norm());
      if (keep[i]) basis.push_back(r.normalized());
    }
  const std::size_t rank = basis.size();
  if (rank == n) return false;
  std::vector<std::size_t> guarded;
  bool found = droppedConstant(system, keep, rows, R0, &guarded);
  // Otherwise another choice of the dependent ones to drop: which one a dependence names is
  // the greedy order's accident (a point's distance dropped where the offsets that hold it
  // were kept, or the reverse).
  std::vector<std::size_t> drop(n - rank);
  for (std::size_t i = 0; i < drop.size(); ++i) drop[i] = i;
  for (int tries = 0; !found && tries < kMostChoices; ++tries) {
    std::fill(keep.begin(), keep.end(), true);
    for (std::size_t i : drop) keep[i] = false;
    found = independent(rows, keep) && droppedConstant(system, keep, rows, R0, &guarded);
    if (!found && !nextChoice(&drop, n)) break;
  }
  if (!found) return false;
  // The guard of a skew distance dropped as constant only where its lines are not parallel:
  // the cosine of their angle kept within halfway from its value at the base to ±1.
  std::vector<Condition> guards;
  for (std::size_t i : guarded) {
    Condition g = system.equations[i];
    g.kind = ConditionKind::kCosine;
    const double at_base = std::abs((R0 * vec(g.u)).dot(vec(g.d)));
    if (!(at_base < 1.0)) return false;
    g.hi = 0.5 * (1.0 + at_base);
    g.lo = -g.hi;
    guards.push_back(g);
  }
  *reduced = system;
  reduced->equations.clear();
  for (std::size_t i = 0; i < n; ++i)
    (keep[i] ? reduced->equations : *dropped).push_back(system.equations[i]);
  reduced->inequalities.insert(reduced->inequalities.end(), guards.begin(), guards.end());
  return true;
}

SourceMask dependentSources(const ConditionSystem& system, const Matrix3d& R0,
                            const Vector3d& t0) {
  const auto n = static_cast<Eigen::Index>(system.equations.size());
  if (n == 0) return 0;
  const std::vector<Vector6d> rows = gradientsAt(system, R0, t0);
  Eigen::MatrixXd J(n, 6);
  for (Eigen::Index i = 0; i < n; ++i) J.row(i) = rows[static_cast<std::size_t>(i)].transpose();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (!(sv.size() > 0 && sv[0] > 0.0)) return 0;
  SourceMask involved = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    // the k-th combination of the equations: its gradient is σ_k (none past the sixth)
    if (k < sv.size() && sv[k] > 1e-6 * sv[0]) continue;
    for (Eigen::Index i = 0; i < n; ++i)
      if (std::abs(svd.matrixU()(i, k)) > 0.1)
        involved |= sourceBit(system.equations[static_cast<std::size_t>(i)].source);
  }
  return involved;
}

}  // namespace relpos::complete::detail
