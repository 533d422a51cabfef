#pragma once
// A cylinder: a point-line distance p > 0 (PL, PMF Table V).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Cylinder : OneConstraintShape<Cylinder> {
  static constexpr const char* kName = "Cylinder";
  static constexpr const char* kSummary = "2 DOF: point-line distance";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 2; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
