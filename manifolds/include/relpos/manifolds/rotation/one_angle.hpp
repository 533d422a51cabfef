#pragma once
// 2 rotational DOF: R(φ, θ) = R(u_f, φ) R0 R(u_m, θ), angle(R u_m, u_f) = α (PMF eq. 4).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct OneAngle : ShapeBase<OneAngle> {
  static constexpr const char* kName = "OneAngle";
  static constexpr const char* kSummary =
      "2 DOF: one vector on a cone about a fixed direction (PMF eq. 4)";
  OneAngle(const Vector3d& u_m, const Vector3d& u_f, double alpha);
  Vector3d u_m, u_f;
  Matrix3d R0;

  int dof() const { return 2; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // The cone's vector nearest R u_m (its azimuth), then the best spin: the angle between a
  // rotation and the nearest one taking u_m to a vector v is the angle between R u_m and v.
  bool projectsExactly() const { return true; }
  Matrix3d baseRotation() const { return R0; }
  const Vector3d* spinAxis() const { return &u_m; }
  Matrix3d spinBase(const double* theta) const;
};

// The turn φ about u_f that puts R0 u_m at the azimuth of R u_m (both taken across u_f): a cone's
// φ for R, exact for R on the cone. NaN where either vector lies along u_f (no azimuth).
double coneAzimuth(const Vector3d& u_m, const Vector3d& u_f, const Matrix3d& R0, const Matrix3d& R);

}  // namespace relpos::manifolds::rotation
