#pragma once
// 1 rotational DOF: R(φ) = R(u_f, φ) R0, R0 u_m = u_f (PMF eq. 3).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct OneParallel : ShapeBase<OneParallel> {
  static constexpr const char* kName = "OneParallel";
  static constexpr const char* kSummary = "1 DOF: spin about one fixed direction (PMF eq. 3)";
  OneParallel(const Vector3d& u_m, const Vector3d& u_f);
  Vector3d u_m, u_f;
  Matrix3d R0;

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  Matrix3d baseRotation() const { return R0; }
};

}  // namespace relpos::manifolds::rotation
