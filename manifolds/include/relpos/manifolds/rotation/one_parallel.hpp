#pragma once
// 1 rotational DOF: R(φ) = R(u_f, φ) R0, R0 u_m = u_f (PMF eq. 3); φ over a full turn, or over
// an arc where an angle range on another mobile vector holds (issue 16: a keyway within ±10°).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct OneParallel : ShapeBase<OneParallel> {
  static constexpr const char* kName = "OneParallel";
  static constexpr const char* kSummary = "1 DOF: spin about one fixed direction (PMF eq. 3)";
  OneParallel(const Vector3d& u_m, const Vector3d& u_f);
  Vector3d u_m, u_f;
  Matrix3d R0;
  // The spin's arc (a full turn unless a matcher narrows it; phi_hi − phi_lo < 2π otherwise).
  double phi_lo = -kPi, phi_hi = kPi;
  bool phi_periodic = true;

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // The best spin about u_f, on its arc the end nearer to it in angle.
  bool projectsExactly() const { return true; }
  Matrix3d baseRotation() const { return R0; }
  // R(u_f, φ) R0 = R0 R(u_m, φ) (R0 u_m = u_f): a spin about u_m, its only parameter.
  const Vector3d* spinAxis() const { return &u_m; }
  int spinIndex() const { return 0; }
  Matrix3d spinBase(const double* theta) const {
    (void)theta;
    return R0;
  }
};

// φ moved onto the arc [lo, hi] (hi − lo < 2π): itself when on it (modulo 2π), else the end
// nearer in angle.
double ontoArc(double phi, double lo, double hi);

}  // namespace relpos::manifolds::rotation
