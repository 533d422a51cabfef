#pragma once
// Rotational components of separable solutions (PMF Table III, App. III). Each is a small value
// type: R(θ) from parameters, and the projection of a rotation onto the set.
#include "relpos/core/geometry.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds {

enum class RotationKind : unsigned char {
  kFixed,          // 0 DOF: two parallelisms, three angles on right trihedra, discrete solutions
  kOneParallel,    // 1 DOF: R(φ) = R(u_f, φ) R0, R0 u_m = u_f            (PMF eq. 3)
  kOneAngle,       // 2 DOF: R(φ, θ) = R(u_f, φ) R0 R(u_m, θ)              (PMF eq. 4)
  kTwoAngle,       // 1 DOF: R(φ) = R(u_f, φ) R0 R(u_m, θ(φ)), φ in [lo, hi] (App. III-D)
  kFree,           // 3 DOF: R = Rz(yaw) Ry(pitch) Rx(roll)                (PMF eq. 5)
  kOneAngleRange,  // 3 DOF: R(φ, θ, α) = R(u_f, φ) R0(α) R(u_m, θ), α in [lo, hi]
                   // (Somani's OneAngleMinMax, 004 Table VI)
};
const char* toString(RotationKind k);

struct RotationPart {
  RotationKind kind = RotationKind::kFree;
  Matrix3d R0 = Matrix3d::Identity();
  Vector3d u_m = Vector3d::UnitZ(), u_f = Vector3d::UnitZ();
  // kTwoAngle: the second constraint angle(R v_m, v_f) = beta, the branch sign and φ bounds.
  Vector3d v_m = Vector3d::UnitX(), v_f = Vector3d::UnitX();
  double cos_beta = 1.0;
  double sign = 1.0;
  double phi_lo = -kPi, phi_hi = kPi;
  bool phi_periodic = true;
  // kOneAngleRange: the bounds of the angle between R u_m and u_f; the cone's base turns about
  // cone_axis (u_m × u_f, or a perpendicular) by cone_beta − α, cone_beta = angle(u_m, u_f).
  double alpha_lo = 0.0, alpha_hi = kPi;
  Vector3d cone_axis = Vector3d::UnitX();
  double cone_beta = 0.0;

  int dof() const;
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  // kOneAngle, kOneAngleRange: the rotation before the spin, R(θ) = spinBase(θ) R(u_m, θ[1]).
  Matrix3d spinBase(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;

  static RotationPart fixed(const Matrix3d& R);
  static RotationPart oneParallel(const Vector3d& u_m, const Vector3d& u_f);
  static RotationPart oneAngle(const Vector3d& u_m, const Vector3d& u_f, double alpha);
  static RotationPart free();
  static RotationPart oneAngleRange(const Vector3d& u_m, const Vector3d& u_f, double lo, double hi);
};

// θ(φ) of a two-angle rotation; false when φ is outside the valid set (beyond rounding).
bool twoAngleTheta(const RotationPart& r, double phi, double* theta);

}  // namespace relpos::manifolds
