#pragma once
// A feature placed in world coordinates, and the angle between two directions as docs/spec.md §1
// measures it: the evaluator's, shared with the tests' other geometry (local DOF, degenerate
// problems) so that they measure what the evaluator measures.
#include <cmath>

#include "relpos/core/problem.hpp"

namespace relpos::test {

struct WorldFeature {
  FeatureKind kind;
  Vector3d a, d;  // the feature's point and unit direction in the world
  double r;
};

inline WorldFeature placeInWorld(const Feature& f, const Isometry3d& X) {
  return {f.kind, X * f.point, (X.linear() * f.direction).normalized(), f.radius};
}

// arccos(u·v) and arcsin(u·v) of SPEC, computed through atan2 so that angles near 0, π and
// ±π/2 keep full precision (acos(1 − ε) would turn rounding into 1e-8 "violations").
inline double angleOf(const Vector3d& u, const Vector3d& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace relpos::test
