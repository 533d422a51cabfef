#include "relpos/core/manifold.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "kink_certificate.hpp"
#include "kink_descent.hpp"
#include "nearest_eval.hpp"
#include "nearest_one_angle.hpp"

namespace relpos {

double poseDistance(const Isometry3d& a, const Isometry3d& b) {
  return (a.translation() - b.translation()).norm() + rotationDistance(a.linear(), b.linear());
}

double Manifold::searchDistance(const Isometry3d& X, Params* theta) const {
  return poseDistance(poseWithTail(X, theta), X);
}

double Manifold::nearestRotation(const Isometry3d& X, Params* theta) const {
  (void)X;
  (void)theta;
  return std::numeric_limits<double>::quiet_NaN();
}

bool Manifold::nearestArc(const Isometry3d& X, int* i, double* lo, double* hi) const {
  (void)X;
  (void)i;
  (void)lo;
  (void)hi;
  return false;
}

double Manifold::rotationCoupling() const { return std::numeric_limits<double>::infinity(); }

bool Manifold::contains(const Isometry3d& X, const Tolerance& tol) const {
  Isometry3d Y = pose(project(X));
  double scale = std::max(1.0, X.translation().norm());
  return (Y.translation() - X.translation()).norm() <= tol.roundTripLength(scale) &&
         rotationDistance(Y.linear(), X.linear()) <= tol.roundTripAngle();
}

namespace {
using detail::clampParam;
using detail::distanceWithTail;

constexpr double kFine = 1e-8;  // the step at which the pattern search ends

// The distance below which X lies on a manifold: the rounding of its coordinates.
double roundingOf(const Isometry3d& X) {
  return 64 * std::numeric_limits<double>::epsilon() * (1.0 + X.translation().norm());
}

// The rounding of a rotation's angle (atan2 of entries exact to a few ulps): X's rotation lies
// among a branch's when a pose of the branch has a rotation this close to it.
constexpr double kRotationRounding = 64 * std::numeric_limits<double>::epsilon();

// Whether a pose Y of m with its closed-form parameters set keeps X's rotation, proven the nearest
// of m (spec §2.6): Y's rotation is X's (to rounding), so X's rotation is among m's, and the
// distance from X's position to the positions m pairs with a rotation R, g(R), moves no farther
// than L ≤ 1 a radian (m.rotationCoupling). Then for every rotation R of m, with R_X X's
// rotation:
//   g(R) + angle(R, R_X) ≥ g(R_X) − L·angle(R, R_X) + angle(R, R_X) ≥ g(R_X),
// and Y, with R_X and its nearest position, is the nearest pose of the branch.
bool keepsRotation(const Manifold& m, const Isometry3d& X, const Isometry3d& Y) {
  if (!(m.rotationCoupling() <= 1.0)) return false;  // +inf (not known) and NaN: no proof
  return rotationDistance(Y.linear(), X.linear()) <= kRotationRounding;
}

// Pattern search (Hooke–Jeeves) on poseDistance from `best` down to a step of `min_step`:
// deterministic, derivative free, monotone. A sweep tries ± step along each parameter; after a
// sweep that improved, the move just made is tried again from the new point (the pattern move),
// which walks a valley in a few evaluations where plain compass steps would zig-zag.
Params patternSearch(const Manifold& m, const Isometry3d& X, const Parameter* par, Params best,
                     double* best_d, double* step, double min_step, bool in_units = false) {
  const int n = m.dof();
  const unsigned fixed = m.closedFormParams();
  auto eval = [&](Params& t) { return distanceWithTail(m, X, fixed, &t); };
  auto sweep = [&](Params base, double* d) {
    for (int i = 0; i < n; ++i) {
      if (fixed & (1u << i)) continue;
      for (double sgn : {1.0, -1.0}) {
        Params t = base;
        const double s = par[i].kind == ParamKind::kLength ? *step * (1.0 + std::abs(base[i]))
                         : in_units                        ? *step * detail::searchUnit(par[i])
                                                           : *step;
        t[i] = clampParam(par[i], t[i] + sgn * s);
        const double dt = eval(t);
        if (dt < *d - 1e-15) {
          *d = dt;
          base = t;
          break;
        }
      }
    }
    return base;
  };
  for (int iter = 0; iter < 400 && *step > min_step; ++iter) {
    double d = *best_d;
    const Params moved = sweep(best, &d);
    if (!(d < *best_d)) {
      *step *= 0.5;
      continue;
    }
    // Pattern move: keep going the way the sweep went while it pays.
    Params base = best;
    best = moved;
    *best_d = d;
    for (int k = 0; k < 8; ++k) {
      Params p = best;
      for (int i = 0; i < n; ++i) p[i] = clampParam(par[i], 2 * best[i] - base[i]);
      double dp = eval(p);
      if (!(dp < *best_d - 1e-15)) break;
      const Params q = sweep(p, &dp);
      base = best;
      best = q;
      *best_d = dp;
    }
  }
  return best;
}

// Newton steps on the searched parameters from `best`, derivatives by central differences of
// step h; a step is taken only when it lowers the distance. Near a smooth minimum each step
// gains digits where a pattern search gains one bit per sweep. *converged: the last step taken
// was shorter than 10 h, or, after a step was taken, a step shorter than 100 h no longer lowers
// the distance (the model's gain is below the distance's rounding: the minimum is reached to
// double precision). *last_step: the length of the last step taken (0: none).
Params newtonPolish(const Manifold& m, const Isometry3d& X, const Parameter* par, Params best,
                    double* best_d, double h, bool* converged, double* last_step) {
  *converged = false;
  *last_step = 0.0;
  const unsigned fixed = m.closedFormParams();
  int idx[kMaxDof];
  const int k = detail::searchedParams(m, idx);
  if (k == 0) return best;
  auto eval = [&](Params t) { return distanceWithTail(m, X, fixed, &t); };
  for (int iter = 0; iter < 8; ++iter) {
    Eigen::Matrix<double, kMaxDof, 1> g = Eigen::Matrix<double, kMaxDof, 1>::Zero();
    Eigen::Matrix<double, kMaxDof, kMaxDof> H = Eigen::Matrix<double, kMaxDof, kMaxDof>::Identity();
    double plus[kMaxDof];
    for (int a = 0; a < k; ++a) {
      Params p = best, q = best;
      p[idx[a]] += h;
      q[idx[a]] -= h;
      plus[a] = eval(p);
      const double minus = eval(q);
      g[a] = (plus[a] - minus) / (2 * h);
      H(a, a) = (plus[a] - 2 * *best_d + minus) / (h * h);
    }
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < a; ++b) {
        Params p = best;
        p[idx[a]] += h;
        p[idx[b]] += h;
        H(a, b) = H(b, a) = (eval(p) - plus[a] - plus[b] + *best_d) / (h * h);
      }
    // A parameter at a bound that the descent would push out of it is held there (projected
    // Newton): its row and column become the identity, its step zero.
    for (int a = 0; a < k; ++a) {
      const Parameter& pa = par[idx[a]];
      const double v = best[idx[a]];
      if (pa.periodic) continue;
      if ((v <= pa.min && g[a] > 0) || (v >= pa.max && g[a] < 0)) {
        H.row(a).setZero();
        H.col(a).setZero();
        H(a, a) = 1.0;
        g[a] = 0.0;
      }
    }
    // Only a positive-definite model has a minimum to step to.
    const Eigen::LLT<Eigen::Matrix<double, kMaxDof, kMaxDof>> llt(H);
    if (llt.info() != Eigen::Success) break;
    Eigen::Matrix<double, kMaxDof, 1> dx = llt.solve(-g);
    // The full step, else shorter ones (far from the minimum the quadratic model overshoots).
    const double full_step = dx.head(k).norm();
    Params t;
    double d = *best_d;
    for (int cut = 0; cut < 4; ++cut, dx *= 0.25) {
      t = best;
      for (int a = 0; a < k; ++a) t[idx[a]] = clampParam(par[idx[a]], t[idx[a]] + dx[a]);
      d = distanceWithTail(m, X, fixed, &t);  // t gets its closed-form parameters
      if (d < *best_d - 1e-15) break;
    }
    if (!(d < *best_d - 1e-15)) {
      if (iter > 0 && full_step < 100 * h) *converged = true;
      break;
    }
    best = t;
    *best_d = d;
    *last_step = dx.head(k).norm();
    if (*last_step < 10 * h) {
      *converged = true;
      break;
    }
  }
  return best;
}

// The general search: a coarse grid over (up to three of) the angles, the pattern search from the
// projection and from the grid's best, Newton from the better. Returns whether Newton converged;
// *step: the step a further pattern search starts from.
bool searchFromProjection(const Manifold& m, const Isometry3d& X, const Parameter* par, Params proj,
                          double proj_d, Params* best_out, double* best_d_out, double* step_out) {
  const int n = m.dof();
  const unsigned fixed = m.closedFormParams();
  int angles[kMaxDof], n_angles = 0;
  for (int i = 0; i < n; ++i)
    if (par[i].kind == ParamKind::kAngle && n_angles < 3 && !(fixed & (1u << i)))
      angles[n_angles++] = i;
  // Periodic or unbounded (a screw's turn): quarter turns from the projection; bounded: four
  // values evenly over the bounds, or only its two ends where it is narrower than half a radian
  // (a torch's tilt range: the pattern search's first steps, a quarter, span it already).
  bool wraps[kMaxDof];
  int values[kMaxDof];
  int combos = 1;
  for (int k = 0; k < n_angles; ++k) {
    const Parameter& p = par[angles[k]];
    wraps[k] = p.periodic || !std::isfinite(p.min) || !std::isfinite(p.max);
    values[k] = !wraps[k] && p.max - p.min < 0.5 ? 2 : 4;
    combos *= values[k];
  }
  Params grid_best = proj;
  double grid_d = std::numeric_limits<double>::infinity();
  for (int c = 1; c < combos; ++c) {  // c = 0 is the projection itself
    Params t = proj;
    for (int k = 0, code = c; k < n_angles; code /= values[k], ++k) {
      const Parameter& p = par[angles[k]];
      const int g = values[k];
      t[angles[k]] = wraps[k] ? t[angles[k]] + 2 * kPi * (code % g) / g
                              : p.min + (p.max - p.min) * (code % g) / (g - 1);
    }
    const double d = distanceWithTail(m, X, fixed, &t);
    if (d < grid_d) grid_d = d, grid_best = t;
  }
  // Both starts through the pattern search at a step of 0.25 (the grid's start wins about a
  // third of the time, often from behind, so both are needed; going straight to Newton from
  // either or both left 1 to 3 branches in 18,750 generated ones in a worse basin), then the
  // better one to the end: Newton, and the pattern search only where Newton did not converge,
  // from about its last step (a kink of the metric: a bound, or a zero translation or rotation
  // distance).
  constexpr double kCoarse = 2e-1;
  double proj_step = 0.25, grid_step = 0.25;
  Params best = patternSearch(m, X, par, proj, &proj_d, &proj_step, kCoarse);
  double best_d = proj_d, best_step = proj_step;
  if (combos > 1) {
    Params other = patternSearch(m, X, par, grid_best, &grid_d, &grid_step, kCoarse);
    if (grid_d < best_d - 1e-12) best = other, best_d = grid_d, best_step = grid_step;
  }
  bool converged = false;
  double last_step = 0.0;
  best = newtonPolish(m, X, par, best, &best_d, 1e-5, &converged, &last_step);
  if (last_step > 0.0) best_step = std::min(best_step, 4 * last_step);
  *best_out = best;
  *best_d_out = best_d;
  *step_out = best_step;
  return converged;
}

// Parameters whose box is narrow (a chart's tangent coordinates, a few thousandths wide): the
// general search's steps, a quarter and down, jump from bound to bound, which finds the corner a
// far pose is nearest but not a minimum inside the box. The pattern search again in the box's own
// unit with the model's steps, from *best and from the nearest corner of the box (a far pose is
// often nearest at a corner, or along an edge from one); the nearer. Nothing for other branches.
void refineInNarrowBox(const Manifold& m, const Isometry3d& X, const Parameter* par, Params* best,
                       double* best_d) {
  int idx[kMaxDof];
  const int k = detail::searchedParams(m, idx);
  bool narrow = false;
  for (int a = 0; a < k; ++a) narrow = narrow || detail::searchUnit(par[idx[a]]) < 1.0;
  if (!narrow) return;
  auto refine = [&](Params* t, double* d) {
    double step = 0.25;
    *t = patternSearch(m, X, par, *t, d, &step, kFine, true);
    detail::descendOnDistanceModel(m, X, par, t, d);
  };
  refine(best, best_d);
  if (k > 4) return;  // 2^k corners
  const unsigned fixed = m.closedFormParams();
  Params corner = *best;
  double corner_d = std::numeric_limits<double>::infinity();
  for (int c = 0; c < (1 << k); ++c) {
    Params t = *best;
    for (int a = 0; a < k; ++a) {
      const Parameter& p = par[idx[a]];
      if (detail::searchUnit(p) < 1.0) t[idx[a]] = (c >> a) & 1 ? p.max : p.min;
    }
    const double d = distanceWithTail(m, X, fixed, &t);
    if (d < corner_d) corner_d = d, corner = t;
  }
  refine(&corner, &corner_d);
  if (corner_d < *best_d) *best = corner, *best_d = corner_d;
}

}  // namespace

Params referenceParams(const Manifold& m) {
  Params t{};
  for (int i = 0, n = m.dof(); i < n; ++i) {
    const Parameter p = m.parameter(i);
    const bool lo = std::isfinite(p.min), hi = std::isfinite(p.max);
    t[i] = lo && hi ? 0.5 * (p.min + p.max) : (lo ? p.min : (hi ? p.max : 0.0));
    if (std::isnan(p.min) || std::isnan(p.max)) t[i] = p.min + p.max;  // NaN: seen by the check
  }
  return t;
}

Params nearestParams(const Manifold& m, const Isometry3d& X) {
  // The projection is exact for poses on the manifold and usually the right basin elsewhere;
  // samples of the angle parameters catch the other basins of the combined metric (translation +
  // rotation). Parameters with a closed form given the others (closedFormParams()) are not
  // searched; one searched angle is a 1-D problem (nearest_one_angle.hpp), more the general
  // search's.
  const int n = m.dof();
  const unsigned fixed = m.closedFormParams();
  // (A branch whose every parameter has a closed form is projected by poseWithTail itself.)
  const bool all_closed_form = detail::allParamsClosedForm(m);
  Params proj = all_closed_form ? Params{} : m.project(X);
  Isometry3d proj_pose = detail::poseWithClosedForms(m, X, fixed, &proj);
  double proj_d = poseDistance(proj_pose, X);
  if (std::isnan(proj_d)) {  // a projection broke down (a NaN anywhere makes the distance NaN)
    proj = referenceParams(m);
    proj_pose = detail::poseWithClosedForms(m, X, fixed, &proj);
    proj_d = poseDistance(proj_pose, X);
    if (std::isnan(proj_d)) return referenceParams(m);
  }
  // A pose on the manifold is its own projection, to the rounding of its coordinates: the search
  // cannot improve on that, and in the combined metric (the translation of the mobile frame's
  // origin) it may trade a rotation too small to see there for one that moves features far from
  // that origin (a part frame 1e6 from its features). Nor can it where the projection keeps X's
  // rotation and no turn gains more in position than it costs in angle: that is the nearest pose.
  if (all_closed_form || proj_d <= roundingOf(X) || keepsRotation(m, X, proj_pose)) return proj;
  Parameter par[kMaxDof];
  for (int i = 0; i < n; ++i) par[i] = m.parameter(i);
  Params best;
  double best_d, best_step;
  bool converged, settled = false;
  int one;
  const bool one_angle = detail::searchesOneBoundedAngle(m, par, &one);
  if (one_angle) {
    // Brent's bracket holds a kink as well as a smooth minimum: what is left to a search at a
    // kink is Brent's last interval, a few times its tolerance (2^-26).
    best = proj, best_d = proj_d, best_step = 1e-6, converged = true;
    // Where the manifold knows the arc the nearest angle lies on, that arc is searched as bounds.
    Parameter searched[kMaxDof];
    std::copy(par, par + n, searched);
    int arc_i = -1;
    double lo = 0.0, hi = 0.0;
    const bool arc = par[one].periodic && m.nearestArc(X, &arc_i, &lo, &hi) && arc_i == one &&
                     lo < hi && hi - lo < 2 * kPi;
    if (arc) searched[one].min = lo, searched[one].max = hi, searched[one].periodic = false;
    settled = detail::nearestAlongOneAngle(m, X, searched, one, arc, &best, &best_d);
  } else {
    converged = searchFromProjection(m, X, par, proj, proj_d, &best, &best_d, &best_step);
  }
  // At a kink of the metric (the rotation or the translation distance zero) differences across it
  // make a curvature of about 1/h, and Newton's steps, that short, look converged where one side
  // still descends. There, a certificate that the point is a minimum ends the search (the rotation
  // already right), else the pattern search goes on from a step that can leave the kink.
  // Near: the rotation within 1e-4 rad of X's, or the translation 1e-4 of the distance.
  enum class Kink { kNone, kRotation, kTranslation };
  auto kinkAt = [&](const Params& t) {
    Params at = t;
    const Isometry3d Y = detail::poseWithClosedForms(m, X, fixed, &at);
    if (rotationDistance(Y.linear(), X.linear()) < 1e-4) return Kink::kRotation;
    return (Y.translation() - X.translation()).norm() < 1e-4 * best_d ? Kink::kTranslation
                                                                      : Kink::kNone;
  };
  Kink kink = Kink::kNone;
  // A certificate's point has its closed-form parameters set (from its residuals): the one-angle
  // search's settled answer, or the kink's below.
  bool tail_set = settled;
  if (!settled) {  // (the one-angle search may have settled its kink already)
    kink = kinkAt(best);
    settled =
        kink != Kink::kNone ? detail::settleOnRotationKink(m, X, par, &best, &best_d) : converged;
    tail_set = settled && kink != Kink::kNone;
  }
  if (!settled) {
    if (kink != Kink::kNone && !one_angle) best_step = std::max(best_step, 1e-2);
    best = patternSearch(m, X, par, best, &best_d, &best_step, kFine);
    // A search that ended beside the kink (to its last step, 1e-8) is moved onto it. Else the
    // pattern search may have stalled on a crease (where the translation pulls the pose off X's
    // rotation: a mobile point far from the origin turned onto X's position), which the
    // distance's convex first-order model steps along.
    const bool on_kink =
        kinkAt(best) == Kink::kRotation && detail::settleOnRotationKink(m, X, par, &best, &best_d);
    if (!on_kink) detail::descendOnDistanceModel(m, X, par, &best, &best_d);
  }
  const Params settled_at = best;
  refineInNarrowBox(m, X, par, &best, &best_d);
  // The closed-form parameters as poseWithTail sets them (searchDistance may leave a spin unset),
  // unless a certificate's point, unmoved since, has them (the same doubles: its own pass).
  if (fixed != 0u && !(tail_set && best == settled_at)) m.poseWithTail(X, &best);
  for (int i = 0; i < n; ++i)
    if (par[i].periodic) best[i] = std::remainder(best[i], 2 * kPi);
  return best;
}

bool nearestIsGlobal(const Manifold& m, const Isometry3d& X, const Isometry3d& nearest,
                     double distance) {
  // A distance that is not a number proves nothing, whatever the parameters.
  if (!std::isfinite(distance)) return false;
  return detail::allParamsClosedForm(m) || distance <= roundingOf(X) ||
         keepsRotation(m, X, nearest);
}

bool nearestIsGlobal(const Manifold& m, const Isometry3d& X, double distance) {
  if (!std::isfinite(distance)) return false;
  if (detail::allParamsClosedForm(m) || distance <= roundingOf(X)) return true;
  return keepsRotation(m, X, m.pose(nearestParams(m, X)));
}

}  // namespace relpos
