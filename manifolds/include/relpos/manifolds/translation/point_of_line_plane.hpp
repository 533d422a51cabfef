#pragma once
// A point: a point on a line that crosses a plane (PL0 ∩ PPl, PMF Table IV).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct PointOfLinePlane : ShapeBase<PointOfLinePlane> {
  static constexpr const char* kName = "Point";
  static constexpr const char* kSummary = "0 DOF: line meets plane";
  PointOfLinePlane(const Fundamental& a, const Fundamental& b) : line(a), plane(b) {}
  Fundamental line, plane;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.line);
    fn(self.plane);
  }

  int dof() const { return 0; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
