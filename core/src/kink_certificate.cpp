#include "kink_certificate.hpp"

#include <Eigen/SVD>
#include <cmath>

#include "nearest_eval.hpp"

namespace relpos::detail {
namespace {

constexpr int kMaxSearched = 3;  // a rotation has three directions: J_r injective needs k ≤ 3
// Fixed-capacity matrices: the search allocates nothing.
using Jacobian = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxSearched>;
using Step = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSearched, 1>;

struct Residuals {
  Vector3d t;  // the translation's: Y's origin − X's
  Vector3d r;  // the rotation's: the axis times the angle of Xᵀ Y
  double d;    // poseDistance(Y, X) = ‖t‖ + ‖r‖
};

Residuals residualsAt(const Manifold& m, const Isometry3d& X, unsigned fixed, Params* t) {
  const Isometry3d Y = poseWithClosedForms(m, X, fixed, t);
  return {Y.translation() - X.translation(), rotationVector(X.linear(), Y.linear()),
          poseDistance(Y, X)};
}

}  // namespace

bool settleOnRotationKink(const Manifold& m, const Isometry3d& X, const Parameter* par,
                          Params* best, double* best_d) {
  const unsigned fixed = m.closedFormParams();
  int idx[kMaxDof];
  const int k = searchedParams(m, idx);
  if (k == 0 || k > kMaxSearched) return false;
  Jacobian Jr(3, k), Jt(3, k);
  for (int iter = 0; iter < 8; ++iter) {
    Params at = *best;
    const Residuals here = residualsAt(m, X, fixed, &at);
    const double angle = here.r.norm();
    if (!(angle < 0.5)) return false;  // far from a kink (or NaN): the smooth search's case
    // Central differences; a nearer probe means *best is no minimum.
    bool probe_nearer = false;
    for (int a = 0; a < k; ++a) {
      const Parameter& p = par[idx[a]];
      const double h = 1e-6 * (p.kind == ParamKind::kLength ? 1.0 + std::abs(at[idx[a]]) : 1.0);
      Params plus = at, minus = at;
      plus[idx[a]] += h;
      minus[idx[a]] -= h;
      const Residuals rp = residualsAt(m, X, fixed, &plus), rm = residualsAt(m, X, fixed, &minus);
      probe_nearer = probe_nearer || rp.d < here.d || rm.d < here.d;
      Jr.col(a) = (rp.r - rm.r) / (2 * h);
      Jt.col(a) = (rp.t - rm.t) / (2 * h);
    }
    const Eigen::JacobiSVD<Jacobian> svd(Jr, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const auto& sigma = svd.singularValues();
    if (!(sigma[k - 1] > 1e-6 * std::max(1.0, sigma[0]))) return false;  // not injective
    if (angle <= 1e-12) {
      // The rotation is X's: the first-order test of the kink.
      const double tn = here.t.norm();
      if (tn == 0.0) return true;  // the pose is X itself
      const Step g = Jt.transpose() * (here.t / tn);
      // (J_rᵀJ_r)⁻¹ = V Σ⁻² Vᵀ.
      const Step w = (svd.matrixV().transpose() * g).cwiseQuotient(sigma);
      return !probe_nearer && w.squaredNorm() < (1.0 - 1e-3) * (1.0 - 1e-3);
    }
    // Gauss–Newton on the rotation's residual: J_r δ = −r.
    const Step delta = svd.solve(-here.r);
    Params next = *best;
    for (int a = 0; a < k; ++a) next[idx[a]] = clampParam(par[idx[a]], next[idx[a]] + delta[a]);
    const double d = distanceWithTail(m, X, fixed, &next);
    if (!(d < *best_d)) return false;
    *best = next;
    *best_d = d;
  }
  return false;
}

}  // namespace relpos::detail
