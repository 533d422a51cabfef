#pragma once
// The one evaluation the nearest-pose search makes (manifold.cpp, kink_certificate.cpp): the pose
// at θ once its closed-form parameters are set, and its distance to X.
#include "relpos/core/manifold.hpp"

namespace relpos::detail {

// pose(θ), with the parameters of m.closedFormParams() (`closed_form`) first set in θ to the
// values nearest X.
inline Isometry3d poseWithClosedForms(const Manifold& m, const Isometry3d& X, unsigned closed_form,
                                      Params* t) {
  return closed_form != 0u ? m.poseWithTail(X, t) : m.pose(*t);
}

// The pose distance at θ once its closed-form parameters are set, as the search weighs it
// (Manifold::searchDistance: the closed-form parameters written into θ may be left unset or
// stale, to be set by poseWithTail before the parameters are read).
inline double distanceWithTail(const Manifold& m, const Isometry3d& X, unsigned closed_form,
                               Params* t) {
  return closed_form != 0u ? m.searchDistance(X, t) : poseDistance(m.pose(*t), X);
}

// The same with every closed-form parameter set in θ.
inline double distanceWithTailSet(const Manifold& m, const Isometry3d& X, unsigned closed_form,
                                  Params* t) {
  return poseDistance(poseWithClosedForms(m, X, closed_form, t), X);
}

// Whether every parameter of m has a closed form: its nearest pose is then set, not searched.
inline bool allParamsClosedForm(const Manifold& m) {
  return m.closedFormParams() == (1u << m.dof()) - 1u;
}

// The parameters the search moves (those without a closed form), their indices into idx; how many.
inline int searchedParams(const Manifold& m, int* idx) {
  const unsigned closed_form = m.closedFormParams();
  int k = 0;
  for (int i = 0; i < m.dof(); ++i)
    if (!(closed_form & (1u << i))) idx[k++] = i;
  return k;
}

// The unit a search in a parameter's own scale measures θ_i in: 1 for an angle or a length (a
// length's step is relative to its size besides), and for a parameter of another kind with
// bounds narrower than ±1 its radius (a chart's tangent coordinates span a box a few thousandths
// wide, which steps of a quarter only jump across).
inline double searchUnit(const Parameter& p) {
  if (p.kind != ParamKind::kOther || !(p.max > p.min) || p.periodic) return 1.0;
  const double radius = 0.5 * (p.max - p.min);
  return radius < 1.0 ? radius : 1.0;
}

// θ_i kept within its bounds (a periodic one wraps instead).
inline double clampParam(const Parameter& p, double v) {
  if (p.periodic) return v;
  return v < p.min ? p.min : (v > p.max ? p.max : v);
}

}  // namespace relpos::detail
