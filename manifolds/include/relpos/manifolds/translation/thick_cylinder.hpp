#pragma once
// A thick cylinder: a point-line distance in [lo, hi] (Somani 004 Table VI).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct ThickCylinder : OneConstraintShape<ThickCylinder> {
  static constexpr const char* kName = "ThickCylinder";
  static constexpr const char* kSummary = "3 DOF: point-line distance within a range";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
