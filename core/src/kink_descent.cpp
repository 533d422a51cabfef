#include "kink_descent.hpp"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace relpos::detail {

namespace {

using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxDof>;

// The kink of the first norm: a + Aδ = 0 (least squares where it cannot be), the second norm least
// along the directions A leaves free.
Step kinkOf(const Jacobian& A, const Vector3d& a, const Jacobian& B, const Vector3d& b) {
  const int k = static_cast<int>(A.cols());
  const Eigen::JacobiSVD<Jacobian> svd(A, Eigen::ComputeThinU | Eigen::ComputeFullV);
  const auto& s = svd.singularValues();
  int rank = 0;
  while (rank < std::min(k, 3) && s[rank] > 1e-9 * std::max(s[0], 1e-300)) ++rank;
  Step at = Step::Zero(k);
  for (int i = 0; i < rank; ++i) at -= svd.matrixV().col(i) * (svd.matrixU().col(i).dot(a) / s[i]);
  if (rank < k) {
    const auto N = svd.matrixV().rightCols(k - rank);
    const Jacobian BN = B * N;
    at += N * BN.completeOrthogonalDecomposition().solve(Vector3d(-(b + B * at)));
  }
  return at;
}

}  // namespace

Step normSumMinimum(const Jacobian& A, const Vector3d& a, const Jacobian& B, const Vector3d& b) {
  const int k = static_cast<int>(A.cols());
  auto f = [&](const Step& d) { return (a + A * d).norm() + (b + B * d).norm(); };
  const Step at_t = kinkOf(A, a, B, b), at_r = kinkOf(B, b, A, a);
  // The smooth minimum: damped Newton from the current point on the convex sum, while both norms
  // stay away from zero (at a kink the gradient is not defined; a kink candidate above holds it).
  Step d = Step::Zero(k);
  double fd = f(d);
  for (int it = 0; it < 30; ++it) {
    const Vector3d ra = a + A * d, rb = b + B * d;
    const double na = ra.norm(), nb = rb.norm();
    if (!(na > 1e-14 * (1.0 + fd) && nb > 1e-14 * (1.0 + fd))) break;
    const Vector3d u = ra / na, v = rb / nb;
    const Step g = A.transpose() * u + B.transpose() * v;
    const Square H = A.transpose() * (Matrix3d::Identity() - u * u.transpose()) * A / na +
                     B.transpose() * (Matrix3d::Identity() - v * v.transpose()) * B / nb;
    Step step = H.ldlt().solve(-g);
    if (!step.allFinite()) break;
    bool lowered = false;
    for (int cut = 0; cut < 40 && !lowered; ++cut, step *= 0.5) {
      const Step next = d + step;
      const double fn = f(next);
      if (fn < fd) d = next, fd = fn, lowered = true;
    }
    if (!lowered || step.norm() <= 1e-16 * (1.0 + d.norm())) break;
  }
  if (f(at_t) < fd) d = at_t, fd = f(at_t);
  if (f(at_r) < fd) d = at_r;
  return d;
}

bool descendOnDistanceModel(const Manifold& m, const Isometry3d& X, const Parameter* par,
                            Params* best, double* best_d) {
  const unsigned fixed = m.closedFormParams();
  int idx[kMaxDof];
  const int k = searchedParams(m, idx);
  if (k == 0) return false;
  for (int iter = 0; iter < 8; ++iter) {
    Params at = *best;
    const Linearisation l = linearise(m, X, par, idx, k, &at);
    if (!std::isfinite(l.here.d)) return false;
    // Both residuals together must move with every parameter, else the model has no bounded
    // minimum (a direction that changes neither).
    Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxDof> stacked(6, k);
    stacked << l.Jt, l.Jr;
    const Eigen::JacobiSVD<decltype(stacked)> svd(stacked);
    const auto& sigma = svd.singularValues();
    if (!(sigma[k - 1] > 1e-6 * std::max(1.0, sigma[0]))) return false;
    Step delta = normSumMinimum(l.Jt, l.here.t, l.Jr, l.here.r);
    if (delta.norm() <= 1e-10) return !(l.probe_d < l.here.d);
    bool lowered = false;
    for (int cut = 0; cut < 3 && !lowered; ++cut, delta *= 0.25) {
      Params next = *best;
      for (int a = 0; a < k; ++a) next[idx[a]] = clampParam(par[idx[a]], next[idx[a]] + delta[a]);
      const double d = distanceWithTail(m, X, fixed, &next);
      if (d < *best_d) *best = next, *best_d = d, lowered = true;
    }
    if (!lowered) return false;
  }
  return false;
}

}  // namespace relpos::detail
