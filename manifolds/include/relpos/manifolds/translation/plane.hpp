#pragma once
// A plane: a point on a plane (PPl, PMF Table V).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Plane : OneConstraintShape<Plane> {
  static constexpr const char* kName = "Plane";
  static constexpr const char* kSummary = "2 DOF: point on a plane";
  using OneConstraintShape::OneConstraintShape;

  int dof() const { return 2; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
