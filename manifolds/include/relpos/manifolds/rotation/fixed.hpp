#pragma once
// 0 rotational DOF: two parallelisms, three angles on right trihedra, discrete solutions
// (PMF App. III-A, III-C).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct Fixed : ShapeBase<Fixed> {
  static constexpr const char* kName = "Fixed";
  static constexpr const char* kSummary =
      "0 rotational DOF: two parallelisms or three angles on right trihedra (PMF Table III)";
  // The nearest rotation to R: R may come from vectors orthogonal only to the angle tolerance.
  explicit Fixed(const Matrix3d& R);
  Matrix3d R0;

  int dof() const { return 0; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // Its only rotation.
  bool projectsExactly() const { return true; }
  Matrix3d baseRotation() const { return R0; }
};

}  // namespace relpos::manifolds::rotation
