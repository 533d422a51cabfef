#pragma once
// R³: no translational constraint.
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Free : ShapeBase<Free> {
  static constexpr const char* kName = "R3";
  static constexpr const char* kSummary = "3 DOF: no translational constraint";
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    (void)self;
    (void)fn;
  }

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
