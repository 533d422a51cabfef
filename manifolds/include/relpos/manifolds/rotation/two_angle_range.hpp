#pragma once
// One mobile vector m within two angle ranges of two fixed directions (issue 16: a weld torch's
// work and travel angles, a camera's two viewing angles), the spin about m free:
// R = R(c → d) Rc R(m, θ), d = R m at angle α ∈ [a_lo, a_hi] from u1 and β from u2, on one side
// (`side`) of the plane of u1 and u2, Rc m = c = side·(u1 × u2)/|u1 × u2|. The directions at two
// given angles from two fixed ones are mirror images across that plane (PMF App. II), so the
// set is at most two pieces, one a branch each; where they meet (d in the plane) both hold it.
// β is a parameter in [b_lo, b_hi] when every α of the range meets all of it (the usual case);
// otherwise the triangle inequalities of α, β and σ = angle(u1, u2) cut the box, and the third
// parameter is β's place between its bounds at α (0 to 1). With α exact (a_lo = a_hi), 2 DOF:
// β (within the bounds α allows) and the spin.
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct TwoAngleRange : ShapeBase<TwoAngleRange> {
  static constexpr const char* kName = "TwoAngleMinMax";
  static constexpr const char* kSummary =
      "2-3 DOF: one vector within ranges of angles from two fixed directions, spin free";
  // u1 and u2 must not be parallel; a_lo ≤ a_hi, b_lo ≤ b_hi within [0, π].
  TwoAngleRange(const Vector3d& m, const Vector3d& u1, double a_lo, double a_hi,
                const Vector3d& u2, double b_lo, double b_hi, double side);
  Vector3d m, u1, u2;
  double a_lo, a_hi, b_lo, b_hi;
  double side;
  double sigma;         // angle(u1, u2)
  Vector3d e2, e3;      // e2 ⊥ u1 in the plane of u1 and u2, e3 = u1 × e2
  Matrix3d Rc;          // Rc m = side·e3
  bool fraction;        // the third parameter is β's place, not β

  // Whether any direction meets both ranges on this side (the α range where β's bounds meet).
  bool empty() const;
  // β's bounds at α: the range clipped by |α − σ| ≤ β ≤ min(α + σ, 2π − α − σ).
  void betaBounds(double alpha, double* lo, double* hi) const;
  // d at angles α and β (β within its bounds), on this side.
  Vector3d direction(double alpha, double beta) const;

  int dof() const { return a_lo == a_hi ? 2 : 3; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  const Vector3d* spinAxis() const { return &m; }
  Matrix3d spinBase(const double* theta) const;
  Matrix3d baseRotation() const { return Rc; }

 private:
  // α's range where β's bounds meet.
  void alphaBounds(double* lo, double* hi) const;
  // (α, β) of parameters θ.
  void angles(const double* theta, double* alpha, double* beta) const;
};

}  // namespace relpos::manifolds::rotation
