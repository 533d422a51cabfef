#pragma once
// 3 rotational DOF: R = Rz(yaw) Ry(pitch) Rx(roll) (PMF eq. 5).
#include "relpos/manifolds/rotation/shape.hpp"

namespace relpos::manifolds::rotation {

struct Free : ShapeBase<Free> {
  static constexpr const char* kName = "Free";
  static constexpr const char* kSummary = "3 DOF: roll, pitch, yaw (PMF eq. 5)";

  int dof() const { return 3; }
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // R itself.
  bool projectsExactly() const { return true; }
};

}  // namespace relpos::manifolds::rotation
