#pragma once
// A slab: a signed point-plane distance in [lo, hi] (Somani's infinite Box, 004 Table VI).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Slab : OneConstraintShape<Slab> {
  static constexpr const char* kName = "Box";
  static constexpr const char* kSummary =
      "3 DOF: point-plane distance within a signed range (an infinite box)";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
