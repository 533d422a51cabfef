#include "relpos/core/manifold.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relpos {

double poseDistance(const Isometry3d& a, const Isometry3d& b) {
  return (a.translation() - b.translation()).norm() + rotationDistance(a.linear(), b.linear());
}

bool Manifold::contains(const Isometry3d& X, const Tolerance& tol) const {
  Isometry3d Y = pose(project(X));
  double scale = std::max(1.0, X.translation().norm());
  return (Y.translation() - X.translation()).norm() <= 1e3 * tol.length * scale &&
         rotationDistance(Y.linear(), X.linear()) <= 1e3 * tol.angle + 1e-7;
}

namespace {
double clampParam(const Parameter& p, double v) {
  if (p.periodic) return v;
  return std::min(std::max(v, p.min), p.max);
}
}  // namespace

namespace {

// Compass search on poseDistance from `start`: deterministic, derivative free, monotone.
Params compassSearch(const Manifold& m, const Isometry3d& X, const Parameter* par, Params best,
                     double* best_d) {
  const int n = m.dof();
  double step = 0.25;
  for (int iter = 0; iter < 200 && step > 1e-8; ++iter) {
    bool improved = false;
    for (int i = 0; i < n; ++i) {
      for (double sgn : {1.0, -1.0}) {
        Params t = best;
        double s = par[i].kind == ParamKind::kLength ? step * (1.0 + std::abs(best[i])) : step;
        t[i] = clampParam(par[i], t[i] + sgn * s);
        double d = poseDistance(m.pose(t), X);
        if (d < *best_d - 1e-15) {
          *best_d = d;
          best = t;
          improved = true;
        }
      }
    }
    if (!improved) step *= 0.5;
  }
  return best;
}

}  // namespace

Params nearestParams(const Manifold& m, const Isometry3d& X) {
  // The projection is exact for poses on the manifold and usually the right basin elsewhere; a
  // coarse grid over the angle parameters catches the other basins of the combined metric
  // (translation + rotation), and a compass search refines the two best starts.
  const int n = m.dof();
  Params proj = m.project(X);
  double proj_d = poseDistance(m.pose(proj), X);
  if (n == 0 || proj_d == 0.0) return proj;
  Parameter par[kMaxDof];
  int angles[kMaxDof], n_angles = 0;
  for (int i = 0; i < n; ++i) {
    par[i] = m.parameter(i);
    if (par[i].kind == ParamKind::kAngle && n_angles < 3) angles[n_angles++] = i;
  }
  constexpr int kGrid = 4;
  Params grid_best = proj;
  double grid_d = std::numeric_limits<double>::infinity();
  int combos = 1;
  for (int k = 0; k < n_angles; ++k) combos *= kGrid;
  for (int c = 1; c < combos; ++c) {  // c = 0 is the projection itself
    Params t = proj;
    for (int k = 0, code = c; k < n_angles; ++k, code /= kGrid) {
      const Parameter& p = par[angles[k]];
      // Periodic or unbounded (a screw's turn): quarter turns from the projection; bounded:
      // evenly over the bounds.
      const bool wraps = p.periodic || !std::isfinite(p.min) || !std::isfinite(p.max);
      t[angles[k]] = wraps ? t[angles[k]] + 2 * kPi * (code % kGrid) / kGrid
                           : p.min + (p.max - p.min) * (code % kGrid) / (kGrid - 1);
    }
    const double d = poseDistance(m.pose(t), X);
    if (d < grid_d) grid_d = d, grid_best = t;
  }
  Params best = compassSearch(m, X, par, proj, &proj_d);
  double best_d = proj_d;
  if (combos > 1) {
    Params other = compassSearch(m, X, par, grid_best, &grid_d);
    if (grid_d < best_d - 1e-12) best = other, best_d = grid_d;
  }
  for (int i = 0; i < n; ++i)
    if (par[i].periodic) best[i] = std::remainder(best[i], 2 * kPi);
  return best;
}

}  // namespace relpos
