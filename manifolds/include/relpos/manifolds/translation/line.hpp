#pragma once
// A line: a point on a line (PL0, PMF Table V).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Line : OneConstraintShape<Line> {
  static constexpr const char* kName = "Line";
  static constexpr const char* kSummary = "1 DOF: point on a line";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
