#pragma once
// An ellipse: a point-line distance p > 0 and a plane its axis crosses (PL p ∩ PPl, PMF eq. 10).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Ellipse : ShapeBase<Ellipse> {
  static constexpr const char* kName = "Ellipse";
  static constexpr const char* kSummary = "1 DOF: point-line distance and point on a plane";
  Ellipse(const Fundamental& a, const Fundamental& b) : cylinder(a), plane(b) {}
  Fundamental cylinder, plane;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.cylinder);
    fn(self.plane);
  }

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
  // Not the foot point: the parameter is affine (the ellipse's eccentric angle).
  bool projectsExactly() const { return false; }
};

}  // namespace relpos::manifolds::translation
