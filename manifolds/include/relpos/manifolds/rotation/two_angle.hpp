#pragma once
// 1 rotational DOF over an interval of φ: two angle constraints (PMF App. III-D),
// R(φ) = R(u_f, φ) R0 R(u_m, θ(φ)) with angle(R v_m, v_f) = β fixing θ(φ) on one branch (sign).
#include "relpos/manifolds/rotation/one_angle.hpp"
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct TwoAngle : ShapeBase<TwoAngle> {
  static constexpr const char* kName = "TwoAngle";
  static constexpr const char* kSummary =
      "1 DOF over phi intervals: two angle constraints (PMF App. III-D)";
  // The first angle's cone (its u_m, u_f and R0), the second angle's vectors and cos β; the
  // branch sign +1 and φ over a full turn until the matcher narrows them.
  TwoAngle(const OneAngle& first, const Vector3d& v_m, const Vector3d& v_f, double cos_beta);
  Vector3d u_m, u_f;
  Matrix3d R0;
  Vector3d v_m, v_f;
  double cos_beta;
  double sign = 1.0;
  double phi_lo = -kPi, phi_hi = kPi;
  bool phi_periodic = true;

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  Matrix3d baseRotation() const { return R0; }
  // θ(φ); false when φ is outside the valid set (beyond rounding).
  bool theta(double phi, double* theta) const;
};

}  // namespace relpos::manifolds::rotation
