#pragma once
// 3 rotational DOF: R(φ, θ, α) = R(u_f, φ) R0(α) R(u_m, θ), α = angle(R u_m, u_f) in [lo, hi]
// (Somani's OneAngleMinMax, 004 Table VI). R0(α) turns u_m about cone_axis (u_m × u_f, or a
// perpendicular) by cone_beta − α, cone_beta = angle(u_m, u_f).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct OneAngleRange : ShapeBase<OneAngleRange> {
  static constexpr const char* kName = "OneAngleMinMax";
  static constexpr const char* kSummary =
      "3 DOF: one vector within a range of angles from a fixed direction (Somani 004 Table VI)";
  OneAngleRange(const Vector3d& u_m, const Vector3d& u_f, double lo, double hi);
  Vector3d u_m, u_f;
  double alpha_lo, alpha_hi;
  Vector3d cone_axis;
  double cone_beta;

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // As for one angle, with R u_m's angle from u_f clamped to the range: the band's vector
  // nearest R u_m.
  bool projectsExactly() const { return true; }
  const Vector3d* spinAxis() const { return &u_m; }
  Matrix3d spinBase(const double* theta) const;
};

}  // namespace relpos::manifolds::rotation
