#include "implied_equations.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace relpos::complete::detail {
namespace {

// A normal within this of the earlier ones' span is in it (dependent everywhere, not by a
// coincidence of the pose): far below any tolerance, far above the rounding of normalised data.
constexpr double kInSpan = 1e-13;
// A cosine this small is a right angle's (cos(π/2) rounds to 6e-17): its row holds the direction
// across its normal to within this times the reach, far below any tolerance.
constexpr double kZeroCosine = 1e-15;

bool linear(const Condition& c) {
  return c.kind == ConditionKind::kPointPlane || c.kind == ConditionKind::kCosine;
}

// Whether a and b read the same unknown: the same mobile point (plane offsets) or direction.
bool sameUnknown(const Condition& a, const Condition& b) {
  if (a.kind != b.kind) return false;
  return a.kind == ConditionKind::kPointPlane ? a.p == b.p : a.u == b.u;
}

// The equation as d·z = b, z the mobile point x or direction R u.
double valueOf(const Condition& c) {
  return c.kind == ConditionKind::kPointPlane ? vec(c.d).dot(vec(c.q)) + c.lo : c.lo;
}

}  // namespace

void dropImpliedEquations(ConditionSystem* system, double length_tolerance, double angle_tolerance,
                          std::vector<ImpliedEquation>* dropped) {
  dropped->clear();
  std::vector<Condition> kept;
  for (const Condition& c : system->equations) {
    if (!linear(c)) {
      kept.push_back(c);
      continue;
    }
    // the earlier linear equations on the same unknown
    Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> N(3, 0);
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1> b(0);
    for (const Condition& e : kept)
      if (linear(e) && sameUnknown(e, c) && N.cols() < 3) {
        N.conservativeResize(3, N.cols() + 1);
        N.col(N.cols() - 1) = vec(e.d);
        b.conservativeResize(b.size() + 1);
        b[b.size() - 1] = valueOf(e);
      }
    if (N.cols() > 0) {
      const Vector3d d = vec(c.d);
      const Eigen::VectorXd alpha = N.colPivHouseholderQr().solve(d);
      const double residual = (d - N * alpha).norm();
      if (residual <= kInSpan * d.norm()) {
        const double mismatch = std::abs(alpha.dot(b) - valueOf(c));
        const double tol = toleranceInUnits(c, length_tolerance, angle_tolerance);
        if (mismatch <= 0.5 * tol && std::isfinite(mismatch)) {
          dropped->push_back({c, mismatch, residual, alpha.lpNorm<1>()});
          continue;
        }
      }
    }
    kept.push_back(c);
  }
  system->equations = std::move(kept);
}

namespace {

// Greedy rank selection: whether v adds a direction to `basis` (orthonormal, extended by it
// when it does): its part off their span above `gap` of its length.
bool extendsSpan(const Vector3d& v, double gap, std::vector<Vector3d>* basis) {
  Vector3d r = v;
  for (const Vector3d& e : *basis) r -= r.dot(e) * e;
  if (!(r.norm() > gap * v.norm())) return false;
  basis->push_back(r.normalized());
  return true;
}

// The rank gap of the charts (chart.cpp): an angle equation independent of the others there.
constexpr double kRankGap = 1e-7;

}  // namespace

namespace {

// A vector within this of a span (relative to its length) is in it: the structure of the
// decompositions (the same vectors, their cross products), not a coincidence of the pose.
bool inSpan(const Vector3d& v, const std::vector<Vector3d>& basis) {
  Vector3d r = v;
  for (const Vector3d& e : basis) r -= r.dot(e) * e;
  return r.norm() <= kInSpan * v.norm();
}

// What the kept equations hold constant on any connected piece of their set through the base.
struct Pinned {
  bool rotation = false;                 // the angles' rank is 3 in the rotation's coordinates
  std::vector<Vector3d> slides;          // with the rotation pinned: every plane row's normal
  std::vector<std::array<double, 3>> u;  // per mobile direction: its (orthonormal) rows...
  std::vector<std::vector<Vector3d>> rows, zero_rows;  // ...and those of value 0
  std::vector<std::array<double, 3>> p;                // per mobile point: its plane rows' normals
  std::vector<std::vector<Vector3d>> normals;

  // The index of direction k (or −k) among `keys`, of point k with `point`; −1: none.
  static int find(const std::vector<std::array<double, 3>>& keys, const std::array<double, 3>& k,
                  bool point = false) {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == k || (!point && vec(keys[i]) == -vec(k))) return static_cast<int>(i);
    return -1;
  }
  // A direction is pinned by two independent angle rows (then finitely many directions meet
  // them) or by a pinned rotation.
  bool direction(const std::array<double, 3>& d) const {
    const int i = find(u, d);
    return rotation || (i >= 0 && rows[static_cast<std::size_t>(i)].size() >= 2);
  }
  // The span of the point's coordinates held constant: its plane rows' normals (all of them
  // with the rotation pinned: x = R p + t).
  // A point q differing from p along a pinned direction moves with it (x_q − x_p = R (q − p)
  // is pinned): its coordinates along p's normals are held too (a plane offset folds its value
  // into the plane's point, pose_conditions.cpp: the same plane, another point on its normal).
  std::vector<Vector3d> held(const std::array<double, 3>& q) const {
    if (rotation) return slides;
    std::vector<Vector3d> span;
    for (std::size_t i = 0; i < p.size(); ++i) {
      bool moves_with = p[i] == q;
      const Vector3d step = vec(q) - vec(p[i]);
      for (std::size_t k = 0; k < u.size() && !moves_with; ++k)
        moves_with = rows[k].size() >= 2 &&
                     step.cross(vec(u[k])).norm() <= kInSpan * step.norm() * vec(u[k]).norm();
      if (moves_with)
        for (const Vector3d& n : normals[i]) extendsSpan(n, kInSpan, &span);
    }
    return span;
  }
  // A pinned direction perpendicular to the held span of point q (exactly: its value-0 angle
  // rows span the same plane), or along it (their cross product in it).
  bool across(const std::array<double, 3>& d, const std::array<double, 3>& q) const {
    const int i = find(u, d);
    if (i < 0 || zero_rows[static_cast<std::size_t>(i)].size() < 2) return false;
    const std::vector<Vector3d> h = held(q);
    for (const Vector3d& e : h)
      if (!inSpan(e, zero_rows[static_cast<std::size_t>(i)])) return false;
    return h.size() == 2;
  }
  bool along(const std::array<double, 3>& d, const std::array<double, 3>& q) const {
    const int i = find(u, d);
    if (i < 0 || zero_rows[static_cast<std::size_t>(i)].size() < 2) return false;
    const std::vector<Vector3d>& z = zero_rows[static_cast<std::size_t>(i)];
    return inSpan(z[0].cross(z[1]), held(q));
  }
};

// Whether equation c is a constant on the piece where `pinned` holds.
bool constantWhere(const Condition& c, const Pinned& pinned) {
  const std::size_t held = pinned.held(c.p).size();
  switch (c.kind) {
    case ConditionKind::kCosine:
      return pinned.direction(c.u);
    case ConditionKind::kPointPlane:
      return inSpan(vec(c.d), pinned.held(c.p));
    case ConditionKind::kPointPoint:
      return held == 3;
    case ConditionKind::kPointLine: {  // reads x across the fixed line d (to 1e-13 of it)
      if (held == 3) return true;
      const std::vector<Vector3d> h = pinned.held(c.p);
      return h.size() == 2 && std::abs(h[0].dot(vec(c.d))) <= kInSpan &&
             std::abs(h[1].dot(vec(c.d))) <= kInSpan;
    }
    case ConditionKind::kLinePoint:  // reads w and x across w
      return pinned.direction(c.u) && (held == 3 || pinned.across(c.u, c.p));
    case ConditionKind::kPlanePoint:  // reads w and x along w
      return pinned.direction(c.u) && (held == 3 || pinned.along(c.u, c.p));
    case ConditionKind::kSkew:
    case ConditionKind::kSkewSquared:  // reads w and x along w × d, across w
      return pinned.direction(c.u) && (held == 3 || pinned.across(c.u, c.p));
    default:
      return false;
  }
}

}  // namespace

bool reduceDependent(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0,
                     ConditionSystem* reduced, std::vector<Condition>* dropped) {
  dropped->clear();
  std::array<Dual<double>, 6> y;
  for (int i = 0; i < 6; ++i) y[i] = Dual<double>::variable(0.0, i);
  const LocalPose<Dual<double>> X(y);
  // the equations independent at the base (greedily, in their canonical order): the linear
  // ones first — what pins directions and points — then the others, which read them
  std::vector<Eigen::Matrix<double, 6, 1>> basis;
  std::vector<bool> keep(system.equations.size(), false);
  for (const bool linear_pass : {true, false})
    for (std::size_t i = 0; i < system.equations.size(); ++i) {
      const Condition& c = system.equations[i];
      if (linear(c) != linear_pass) continue;
      const Dual<double> g = evaluate(inBaseFrame(c, R0, t0), X);
      Eigen::Matrix<double, 6, 1> r, v;
      for (int j = 0; j < 6; ++j) v[j] = g.g[j];
      r = v;
      for (const auto& e : basis) r -= r.dot(e) * e;
      keep[i] = r.norm() > kRankGap * std::max(1.0, v.norm());
      if (keep[i]) basis.push_back(r.normalized());
    }
  if (std::find(keep.begin(), keep.end(), false) == keep.end()) return false;
  // what the kept ones pin
  Pinned pinned;
  std::vector<Vector3d> turns;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const Condition& c = system.equations[i];
    if (!keep[i]) continue;
    if (c.kind == ConditionKind::kCosine) {
      const Dual<double> g = evaluate(inBaseFrame(c, R0, t0), X);
      extendsSpan(Vector3d(g.g[0], g.g[1], g.g[2]), kRankGap, &turns);
      int k = Pinned::find(pinned.u, c.u);
      if (k < 0) {
        k = static_cast<int>(pinned.u.size());
        pinned.u.push_back(c.u), pinned.rows.emplace_back(), pinned.zero_rows.emplace_back();
      }
      extendsSpan(vec(c.d), kInSpan, &pinned.rows[static_cast<std::size_t>(k)]);
      if (std::abs(c.lo) <= kZeroCosine)
        extendsSpan(vec(c.d), kInSpan, &pinned.zero_rows[static_cast<std::size_t>(k)]);
    } else if (c.kind == ConditionKind::kPointPlane) {
      extendsSpan(vec(c.d), kInSpan, &pinned.slides);
      int k = Pinned::find(pinned.p, c.p, true);
      if (k < 0) {
        k = static_cast<int>(pinned.p.size());
        pinned.p.push_back(c.p), pinned.normals.emplace_back();
      }
      extendsSpan(vec(c.d), kInSpan, &pinned.normals[static_cast<std::size_t>(k)]);
    }
  }
  pinned.rotation = turns.size() >= 3;
  *reduced = system;
  reduced->equations.clear();
  for (std::size_t i = 0; i < keep.size(); ++i) {
    const Condition& c = system.equations[i];
    if (keep[i]) {
      reduced->equations.push_back(c);
    } else {
      if (!constantWhere(c, pinned)) return false;
      dropped->push_back(c);
    }
  }
  return true;
}

double impliedViolation(const ImpliedEquation& e, double reach, double earlier) {
  // d·z − b = (b' − b) + Σα_k (n_k·z − b_k) + r·z, |z| ≤ reach (a direction: 1)
  const double z = e.condition.kind == ConditionKind::kPointPlane ? reach : 1.0;
  return e.mismatch + e.weight * earlier + e.residual * z;
}

}  // namespace relpos::complete::detail
