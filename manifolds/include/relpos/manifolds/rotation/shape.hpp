#pragma once
// What every rotation shape of a separable branch provides (PMF Table III, App. III). Each shape
// is a small value type in its own header and source, held in RotationShape (shapes.hpp) and
// called through std::visit: no virtual call per evaluation, no heap. A shape has
//   static constexpr const char* kName;     // written in results ("rotation OneParallel, ...")
//   static constexpr const char* kSummary;  // the registry's catalogue entry
//   int dof() const;
//   Parameter parameter(int i) const;
//   Matrix3d rotation(const double* theta) const;
//   void project(const Matrix3d& R, double* theta) const;  // the nearest rotation's parameters
// and may replace the defaults of ShapeBase below.
#include "relpos/core/geometry.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds::rotation {

template <typename Derived>
struct ShapeBase {
  // The rotation a matcher checks what holds for every rotation of the shape at (relative
  // orientations it does not change): the formulas' base rotation R0, or the identity.
  Matrix3d baseRotation() const { return Matrix3d::Identity(); }
  // The mobile axis u_m of a trailing spin R = spinBase(θ) R(u_m, θ[spinIndex()]), or null: the
  // nearest spin is then closed form when the translation does not move with it. The spin is the
  // second parameter (after the turn that sets u_m's direction), or the only one.
  const Vector3d* spinAxis() const { return nullptr; }
  int spinIndex() const { return 1; }
  Matrix3d spinBase(const double* theta) const {
    (void)theta;
    return Matrix3d::Identity();
  }
  // Whether project() gives the rotation of the shape nearest R in the geodesic angle (a closed
  // form, not a scan): with a translation that does not move with the rotation, the branch's
  // nearest pose is then its projection.
  bool projectsExactly() const { return false; }
};

// A full turn, named `name`.
inline Parameter turnParameter(const char* name) {
  return Parameter{name, ParamKind::kAngle, -kPi, kPi, true};
}

}  // namespace relpos::manifolds::rotation
