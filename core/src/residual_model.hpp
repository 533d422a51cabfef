#pragma once
// The first-order model of the distance the nearest-pose search minimises at a kink
// (kink_certificate.cpp, kink_descent.cpp): the translation's and the rotation's residuals at θ,
// once its closed-form parameters are set, and their Jacobians in the searched parameters.
#include <Eigen/Core>
#include <algorithm>
#include <limits>

#include "nearest_eval.hpp"

namespace relpos::detail {

// Fixed-capacity matrices, one column per searched parameter: the search allocates nothing.
using Jacobian = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxDof>;
using Step = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDof, 1>;

struct Residuals {
  Vector3d t;  // the translation's: Y's origin − X's
  Vector3d r;  // the rotation's: the axis times the angle of Xᵀ Y
  double d;    // poseDistance(Y, X) = ‖t‖ + ‖r‖
};

inline Residuals residualsAt(const Manifold& m, const Isometry3d& X, unsigned closed_form,
                             Params* t) {
  const Isometry3d Y = poseWithClosedForms(m, X, closed_form, t);
  Residuals res;
  res.t = Y.translation() - X.translation();
  double angle;
  res.r = rotationVector(X.linear(), Y.linear(), &angle);
  res.d = res.t.norm() + angle;  // poseDistance(Y, X), its rotation angle computed once
  return res;
}

struct Linearisation {
  Residuals here;  // at θ (its closed-form parameters set)
  Jacobian Jt, Jr;
  // The nearest probe's distance: below here.d, θ is no minimum.
  double probe_d = std::numeric_limits<double>::infinity();
};

// The differences' step, in differenceUnit.
constexpr double kDifferenceStep = 1e-6;

// The unit of the differences' step at θ_i = v: a length's relative to its size, another's the
// search unit.
inline double differenceUnit(const Parameter& p, double v) {
  return p.kind == ParamKind::kLength ? 1.0 + std::abs(v) : searchUnit(p);
}

// The residuals at *at and their Jacobians in the k searched parameters idx by central
// differences (a length's step relative to its size, another's to its search unit): 2k poses.
// `here`: the residuals at *at, once residualsAt has set its closed-form parameters (a caller
// that looks at them first saves the differences where they tell it to stop).
inline Linearisation linearise(const Manifold& m, const Isometry3d& X, const Parameter* par,
                               const int* idx, int k, const Params* at, const Residuals& here) {
  const unsigned closed_form = m.closedFormParams();
  Linearisation l{here, Jacobian(3, k), Jacobian(3, k)};
  for (int a = 0; a < k; ++a) {
    const Parameter& p = par[idx[a]];
    const double h = kDifferenceStep * differenceUnit(p, (*at)[idx[a]]);
    Params plus = *at, minus = *at;
    plus[idx[a]] += h;
    minus[idx[a]] -= h;
    const Residuals rp = residualsAt(m, X, closed_form, &plus);
    const Residuals rm = residualsAt(m, X, closed_form, &minus);
    l.probe_d = std::min({l.probe_d, rp.d, rm.d});
    l.Jr.col(a) = (rp.r - rm.r) / (2 * h);
    l.Jt.col(a) = (rp.t - rm.t) / (2 * h);
  }
  return l;
}

// The same from *at alone (its closed-form parameters set in it): 1 + 2k poses.
inline Linearisation linearise(const Manifold& m, const Isometry3d& X, const Parameter* par,
                               const int* idx, int k, Params* at) {
  const Residuals here = residualsAt(m, X, m.closedFormParams(), at);
  return linearise(m, X, par, idx, k, at, here);
}

}  // namespace relpos::detail
