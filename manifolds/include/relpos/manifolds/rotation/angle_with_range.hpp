#pragma once
// 2 rotational DOF: one mobile vector u_m at an exact angle α from u_f (a cone, PMF eq. 4) and
// another, v_m, within [lo, hi] of v_f (issue 16: a gripper's jaw across a can's axis and its
// approach within 30° of vertical). R = R(u_f, φ) R0 R(u_m, θ): at each φ the angle of R v_m
// from v_f is h(φ) + amp(φ) cos(θ − θ0(φ)) in cosine, so θ lies on two arcs mirrored about
// θ0(φ), θ = θ0 + sign·(ψ_in(φ) + t (ψ_out(φ) − ψ_in(φ))), t ∈ [0, 1] (the parameter
// `theta_fraction`); φ over an interval where the range is reachable. One branch per interval
// and sign; the two signs meet where an arc closes (ψ_in = 0 or ψ_out = π).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct AngleWithRange : ShapeBase<AngleWithRange> {
  static constexpr const char* kName = "AngleWithRange";
  static constexpr const char* kSummary =
      "2 DOF: one vector on a cone, another within a range of angles from a fixed direction";
  AngleWithRange(const Vector3d& u_m, const Vector3d& u_f, double alpha, const Vector3d& v_m,
                 const Vector3d& v_f, double lo, double hi);
  Vector3d u_m, u_f, v_m, v_f;
  Matrix3d R0;
  double cos_lo, cos_hi;  // cos of the range's ends: the band of R v_m · v_f is [cos_hi, cos_lo]
  double sign = 1.0;
  double phi_lo = -kPi, phi_hi = kPi;
  bool phi_periodic = true;

  int dof() const { return 2; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  Matrix3d baseRotation() const { return R0; }

  // θ's arc at φ: θ0 and the offsets ψ_in ≤ ψ_out from it (in [0, π]).
  void arc(double phi, double* theta0, double* psi_in, double* psi_out) const;
};

}  // namespace relpos::manifolds::rotation
