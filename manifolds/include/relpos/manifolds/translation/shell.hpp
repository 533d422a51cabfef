#pragma once
// A thick sphere: a point-point distance in [lo, hi] (Somani 004 Table VI).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Shell : OneConstraintShape<Shell> {
  static constexpr const char* kName = "Shell";
  static constexpr const char* kSummary =
      "3 DOF: point-point distance within a range (a thick sphere)";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
