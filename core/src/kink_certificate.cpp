#include "kink_certificate.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "residual_model.hpp"

namespace relpos::detail {
namespace {

constexpr int kMaxSearched = 3;  // a rotation has three directions: J_r injective needs k ≤ 3

// The largest rotation no step can reach that is still treated as a kink's (the distance's
// curvature across it is about 1/ε, which the model below carries exactly).
constexpr double kNearKink = kKinkReach;
constexpr double kUnreachable = 0.25;

}  // namespace

bool settleOnRotationKink(const Manifold& m, const Isometry3d& X, const Parameter* par,
                          Params* best, double* best_d, double* start_d) {
  const unsigned fixed = m.closedFormParams();
  int idx[kMaxDof];
  const int k = searchedParams(m, idx);
  if (start_d) *start_d = std::numeric_limits<double>::quiet_NaN();
  if (k == 0 || k > kMaxSearched) return false;
  Linearisation l;
  double last_step = std::numeric_limits<double>::infinity();
  // The residuals at *best (its closed-form parameters set in it): first those of *best as given
  // (its distance taken from them where the caller, not having weighed it, passes +inf), then
  // those of each step taken, which weighed it.
  Params at = *best;
  Residuals here = residualsAt(m, X, fixed, &at);
  if (start_d) *start_d = here.d;
  *best = at;
  if (!(*best_d < std::numeric_limits<double>::infinity())) *best_d = here.d;
  for (int iter = 0; iter < 8; ++iter) {
    const double angle = here.r.norm();
    // Far from a kink (or NaN): the smooth search's case, told before the differences' 2k poses.
    if (!(angle < 0.5)) return false;
    // After a step a tenth of the differences' or less (1e-6 in the search's units: the steps onto
    // a kink ε ≈ 1e-8 off X's rotation, an initial pose written with 8 digits), the Jacobians
    // have moved by about the step's fraction of them, far inside the test's 1e-3 margin: they
    // are kept, and only the residuals are new. The probes are then the last ones, within that
    // step of θ.
    if (iter > 0 && last_step <= 0.1 * kDifferenceStep) {
      l.here = here;
    } else {
      l = linearise(m, X, par, idx, k, best, here);
    }
    const Jacobian &Jr = l.Jr, &Jt = l.Jt;
    const bool probe_nearer = l.probe_d < here.d;
    // The model: d(δ) ≈ d + gᵀδ + √(ε² + ‖J_r (δ − δ₀)‖²), with δ₀ = −J_r⁺ r the Gauss–Newton
    // step and ε = ‖r + J_r δ₀‖ the rotation no step can reach (an initial pose written with 8
    // digits misses a reachable rotation by about 1e-8). Convex; where q = gᵀ(J_rᵀJ_r)⁻¹g < 1 its
    // minimum is at δ₀ − ε (J_rᵀJ_r)⁻¹g / √(1 − q): the kink itself for ε = 0.
    const double tn = here.t.norm();
    const Step g = tn > 0.0 ? Step(Jt.transpose() * (here.t / tn)) : Step(Step::Zero(k));
    Step gn(k), Gg(k);  // δ₀ and (J_rᵀJ_r)⁻¹ g
    double q = 0.0;
    if (k == 1) {  // one searched angle (the common case): σ = ‖J_r‖, no decomposition
      const double sigma = Jr.col(0).norm();
      if (!(sigma > 1e-6)) return false;  // not injective
      gn[0] = -Jr.col(0).dot(here.r) / (sigma * sigma);
      Gg[0] = g[0] / (sigma * sigma);
      q = g[0] * Gg[0];
    } else {
      const Eigen::JacobiSVD<Jacobian> svd(Jr, Eigen::ComputeThinU | Eigen::ComputeThinV);
      const auto& sigma = svd.singularValues();
      if (!(sigma[k - 1] > 1e-6 * std::max(1.0, sigma[0]))) return false;  // not injective
      // (J_rᵀJ_r)⁻¹ = V Σ⁻² Vᵀ.
      const Step w = (svd.matrixV().transpose() * g).cwiseQuotient(sigma);
      q = w.squaredNorm();
      Gg = svd.matrixV() * w.cwiseQuotient(sigma);
      gn = svd.solve(-here.r);
    }
    const bool holds = q < (1.0 - 1e-3) * (1.0 - 1e-3);
    const double eps = (here.r + Jr * gn).norm();
    // Far from the kink, ε is the linear model's error as much as the rotation's: plain steps.
    const bool near = eps <= kNearKink;
    // Most of the rotation out of the parameters' reach: X's rotation is no kink of the branch
    // near here (a reachable one leaves ε of the model's second-order error, about angle²).
    if (!near && eps > kUnreachable * angle) return false;
    const Step delta = holds && near ? Step(gn - (eps / std::sqrt(1.0 - q)) * Gg) : gn;
    // At the model's minimum (the rotation X's, or a step below what the distance can resolve):
    // the first-order test of the kink.
    if (angle <= 1e-12 || (near && delta.norm() <= 1e-10)) return holds && !probe_nearer;
    Params next = *best;
    last_step = 0.0;
    for (int a = 0; a < k; ++a) {
      next[idx[a]] = clampParam(par[idx[a]], next[idx[a]] + delta[a]);
      const double moved = std::abs(next[idx[a]] - (*best)[idx[a]]);
      last_step = std::max(last_step, moved / differenceUnit(par[idx[a]], (*best)[idx[a]]));
    }
    // Weighed by its residuals, which the next round reads (not by searchDistance, then again).
    here = residualsAt(m, X, fixed, &next);
    if (!(here.d < *best_d)) return false;
    *best = next;
    *best_d = here.d;
  }
  return false;
}

}  // namespace relpos::detail
