#include "implied_equations.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

namespace relpos::complete::detail {
namespace {

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

double impliedViolation(const ImpliedEquation& e, double reach, double earlier) {
  // d·z − b = (b' − b) + Σα_k (n_k·z − b_k) + r·z, |z| ≤ reach (a direction: 1)
  const double z = e.condition.kind == ConditionKind::kPointPlane ? reach : 1.0;
  return e.mismatch + e.weight * earlier + e.residual * z;
}

}  // namespace relpos::complete::detail
