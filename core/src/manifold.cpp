#include "relpos/core/manifold.hpp"

#include <algorithm>
#include <cmath>

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

Params nearestParams(const Manifold& m, const Isometry3d& X) {
  // Compass search: deterministic, derivative free, monotone. The projection is exact for poses
  // on the manifold and a good seed elsewhere; the search trades a little translation for
  // rotation (or back) where the combined metric prefers it.
  const int n = m.dof();
  Params best = m.project(X);
  double best_d = poseDistance(m.pose(best), X);
  if (n == 0 || best_d == 0.0) return best;
  Parameter par[kMaxDof];
  for (int i = 0; i < n; ++i) par[i] = m.parameter(i);
  double step = 0.25;
  for (int iter = 0; iter < 200 && step > 1e-10; ++iter) {
    bool improved = false;
    for (int i = 0; i < n; ++i) {
      for (double sgn : {1.0, -1.0}) {
        Params t = best;
        double s = par[i].kind == ParamKind::kLength ? step * (1.0 + std::abs(best[i])) : step;
        t[i] = clampParam(par[i], t[i] + sgn * s);
        double d = poseDistance(m.pose(t), X);
        if (d < best_d - 1e-15) {
          best_d = d;
          best = t;
          improved = true;
        }
      }
    }
    if (!improved) step *= 0.5;
  }
  for (int i = 0; i < n; ++i)
    if (par[i].periodic) best[i] = std::remainder(best[i], 2 * kPi);
  return best;
}

}  // namespace relpos
