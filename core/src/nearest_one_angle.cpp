#include "nearest_one_angle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "brent_minimum.hpp"
#include "kink_certificate.hpp"
#include "nearest_eval.hpp"

namespace relpos::detail {
namespace {
// Half the double digits: at a smooth minimum the distance is then exact to rounding (its error is
// quadratic in the angle's).
constexpr double kTolerance = 1.4901161193847656e-08;  // 2^-26
}  // namespace

bool searchesOneBoundedAngle(const Manifold& m, const Parameter* par, int* i) {
  int idx[kMaxDof];
  if (searchedParams(m, idx) != 1) return false;
  const Parameter& p = par[idx[0]];
  *i = idx[0];
  return p.kind == ParamKind::kAngle &&
         (p.periodic || (std::isfinite(p.min) && std::isfinite(p.max) && p.min < p.max));
}

bool nearestAlongOneAngle(const Manifold& m, const Isometry3d& X, const Parameter* par, int i,
                          bool arc, Params* best, double* best_d) {
  const unsigned fixed = m.closedFormParams();
  const Parameter& p = par[i];
  // On an arc, the projection's angle and the kink's (each an atan2's) may lie a turn away.
  const double mid = 0.5 * (p.min + p.max);
  auto onTurn = [&](double v) { return arc ? mid + std::remainder(v - mid, 2 * kPi) : v; };
  (*best)[i] = onTurn((*best)[i]);
  // Every pose weighed is kept if nearest, so Brent's answer needs no evaluation of its own. NaN (a
  // closed form that broke down) counts as farthest: it never wins a comparison.
  auto distanceAt = [&](double v) {
    Params t = *best;
    t[i] = v;
    const double d = distanceWithTail(m, X, fixed, &t);
    if (std::isnan(d)) return std::numeric_limits<double>::infinity();
    if (d < *best_d) *best_d = d, *best = t;
    return d;
  };
  // Twelve samples, 30° apart over a turn (periodic: from the projection, the first sample) or
  // evenly over the bounds, both ends included (a bound is where a ranged minimum often lies); an
  // arc at most 15° apart, its ends included (at 20° and 30°, two basins 0.06–0.09 rad apart,
  // where a grasp's radius switches bounds, fell between two samples, and Brent's bracket held
  // the farther one: the turn's samples had happened to catch the nearer).
  constexpr int kSamples = 12;
  const int n =
      arc ? std::clamp(static_cast<int>(std::ceil((p.max - p.min) / (kPi / 12))) + 1, 3, kSamples)
          : kSamples;
  const double proj = (*best)[i], proj_d = *best_d;
  const double step = p.periodic ? 2 * kPi / kSamples : (p.max - p.min) / (n - 1);
  // Brent (a kink is the caller's to settle), from the sample, over the two steps
  // around each of the two nearest samples that are nearer than their neighbours. Not only the
  // nearest: where the angle moves a point far (an ellipse 100 long), a basin 10° wide may hide
  // between samples that are far, and the projection usually lies in it.
  // Near a kink of the rotation (X's rotation reached, or nearly: the distance a V there), Brent
  // converges by golden sections, one bit a pose; the kink's own steps reach it and prove it a
  // minimum in a few. The distance of the point so proven, if it ends the nearest.
  double certified_d = std::numeric_limits<double>::quiet_NaN();
  // The certificate from θ_i = centre (its distance centre_d; +inf: not weighed yet, the
  // certificate weighs it, into *start_d if given): true when it settles a kink there, its angle
  // then in *settled_at; a nearer point its steps reach is kept either way.
  auto settleFrom = [&](double centre, double centre_d, double* settled_at,
                        double* start_d = nullptr) {
    Params at = *best;
    at[i] = centre;
    double at_d = centre_d;
    if (!settleOnRotationKink(m, X, par, &at, &at_d, start_d)) {
      if (at_d < *best_d) *best = at, *best_d = at_d;  // its steps only ever lower the distance
      return false;
    }
    if (at_d <= *best_d) *best = at, *best_d = certified_d = at_d;
    *settled_at = at[i];
    return true;
  };
  // Where the manifold knows in closed form where its rotation comes nearest X's: reached there
  // (within the certificate's reach), that is the kink, and the certificate settles it from there
  // in a step or two, where from a sample up to 15° off it steps there first, new differences each
  // step. Out of reach there, no point of the branch is a kink: no certificate is tried at all.
  Params kink = *best;
  const double kink_angle = m.nearestRotation(X, &kink);
  const bool out_of_reach = kink_angle > 2 * kKinkReach;     // (NaN, not known: false)
  double kink_v = std::numeric_limits<double>::quiet_NaN();  // the kink settled there, if one
  // The kink's angle and distance, where the certificate starts (its own first residuals weigh
  // it): a sample within 1e-5 of it is taken there (an arc's end, 1e-6 beyond the kink).
  double kink_at = std::numeric_limits<double>::quiet_NaN(), kink_d = kink_at;
  if (kink_angle <= 2 * kKinkReach) {
    kink_at = clampParam(p, onTurn(kink[i]));
    settleFrom(kink_at, std::numeric_limits<double>::infinity(), &kink_v, &kink_d);
    // Not weighed there (no certificate for this branch): no sample is taken for it.
    if (std::isnan(kink_d)) kink_at = std::numeric_limits<double>::quiet_NaN();
  }
  double v[kSamples], d[kSamples];
  for (int s = 0; s < n; ++s) {
    // The last sample is the upper bound itself, not min + (n − 1)·step (a few ulps short of it).
    v[s] = p.periodic ? proj + s * step : (s + 1 < n ? p.min + s * step : p.max);
    if (p.periodic && s == 0)
      d[s] = proj_d;
    else if (std::abs(v[s] - kink_at) <= 1e-5)
      v[s] = kink_at, d[s] = kink_d;
    else
      d[s] = distanceAt(v[s]);
  }
  auto refineAround = [&](double centre, double centre_d) {
    // A settled kink within the sample's two steps is this basin's minimum (NaN: none settled).
    const double apart = p.periodic ? std::remainder(centre - kink_v, 2 * kPi) : centre - kink_v;
    if (std::abs(apart) <= step) return;
    double settled_at;
    if (!out_of_reach && settleFrom(centre, centre_d, &settled_at)) return;
    double lo = centre - step, hi = centre + step;
    if (!p.periodic) lo = std::max(lo, p.min), hi = std::min(hi, p.max);
    brentMinimumFrom(distanceAt, lo, hi, centre, centre_d, kTolerance, 60);
  };
  int first = -1, second = -1;
  for (int s = 0; s < n; ++s) {
    const bool has_before = p.periodic || s > 0, has_after = p.periodic || s + 1 < n;
    const double before = d[(s + n - 1) % n], after = d[(s + 1) % n];
    if ((has_before && before < d[s]) || (has_after && after < d[s])) continue;
    if (first < 0 || d[s] < d[first]) {
      second = first, first = s;
    } else if (second < 0 || d[s] < d[second]) {
      second = s;
    }
  }
  // A bounded angle's projection lies off the samples: its basin is a candidate of its own.
  // (On an arc, a projection off it is no candidate: the nearest pose is on it.)
  const bool proj_off_lattice =
      !p.periodic && (first < 0 || proj_d < d[first]) && (!arc || (proj >= p.min && proj <= p.max));
  if (first >= 0) refineAround(v[first], d[first]);
  if (proj_off_lattice)
    refineAround(proj, proj_d);
  else if (second >= 0)
    refineAround(v[second], d[second]);
  return *best_d == certified_d;
}

}  // namespace relpos::detail
