#pragma once
// A point: a point-point coincidence (PP0, PMF Table V).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Point : OneConstraintShape<Point> {
  static constexpr const char* kName = "Point";
  static constexpr const char* kSummary = "0 DOF: point-point coincidence";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 0; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
