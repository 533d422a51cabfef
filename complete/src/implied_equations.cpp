#include "implied_equations.hpp"

#include <Eigen/QR>
#include <cmath>

namespace relpos::complete::detail {
namespace {

// A normal within this of the earlier ones' span is in it (dependent everywhere, not by a
// coincidence of the pose): far below any tolerance, far above the rounding of normalised data.
constexpr double kInSpan = 1e-13;

Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

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
        const double tol =
            c.kind == ConditionKind::kPointPlane ? length_tolerance : angle_tolerance;
        if (mismatch <= 0.5 * tol && std::isfinite(mismatch)) {
          dropped->push_back({c, mismatch, residual});
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

bool reduceWhereRotationPinned(const ConditionSystem& system, const Matrix3d& R0,
                               const Vector3d& t0, ConditionSystem* reduced,
                               std::vector<Condition>* dropped) {
  dropped->clear();
  std::array<Dual<double>, 6> y;
  for (int i = 0; i < 6; ++i) y[i] = Dual<double>::variable(0.0, i);
  const LocalPose<Dual<double>> X(y);
  std::vector<Vector3d> turns, slides;  // the kept angle rows (rotation part), plane normals
  std::vector<bool> keep(system.equations.size(), true);
  // the angles first: whether they pin the rotation
  for (std::size_t i = 0; i < system.equations.size(); ++i) {
    const Condition& c = system.equations[i];
    if (c.kind != ConditionKind::kCosine) continue;
    const Dual<double> g = evaluate(inBaseFrame(c, R0, t0), X);
    keep[i] = extendsSpan(Vector3d(g.g[0], g.g[1], g.g[2]), kRankGap, &turns);
  }
  if (turns.size() < 3) return false;
  for (std::size_t i = 0; i < system.equations.size(); ++i) {
    const Condition& c = system.equations[i];
    if (c.kind == ConditionKind::kPointPlane) keep[i] = extendsSpan(vec(c.d), kInSpan, &slides);
  }
  *reduced = system;
  reduced->equations.clear();
  for (std::size_t i = 0; i < system.equations.size(); ++i)
    (keep[i] ? reduced->equations : *dropped).push_back(system.equations[i]);
  return !dropped->empty();
}

double impliedViolation(const ImpliedEquation& e, double reach) {
  // d·z − b = (b' − b) + r·z on the others' set, |z| ≤ reach (a direction: 1)
  const double z = e.condition.kind == ConditionKind::kPointPlane ? reach : 1.0;
  return e.mismatch + e.residual * z;
}

}  // namespace relpos::complete::detail
