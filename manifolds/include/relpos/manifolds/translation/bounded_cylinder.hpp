#pragma once
// A point-line distance (exact or ranged) with a point-plane constraint (exact or ranged) on a
// plane the line crosses: an annulus, a finite cylinder or a finite thick cylinder, square or
// oblique (Somani's grasp volumes, oblique cylinder). DOF = 1 (azimuth) + ranged constraints.
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct BoundedCylinder : ShapeBase<BoundedCylinder> {
  static constexpr const char* kName = "BoundedCylinder";
  static constexpr const char* kSummary =
      "1-3 DOF: point-line distance and point-plane constraint on one point, at least one a "
      "range: annulus, finite (thick) cylinder, cut square or obliquely";
  BoundedCylinder(const Fundamental& a, const Fundamental& b) : cylinder(a), plane(b) {}
  Fundamental cylinder, plane;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.cylinder);
    fn(self.plane);
  }

  int dof() const { return 1 + !cylinder.exact() + !plane.exact(); }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
  // project(), then translation(R, t), the shapes placed once (the search does both per pose).
  Vector3d projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const;
  // Square cuts only: an oblique cut's radius and height are clamped along directions that are
  // not orthogonal. (Line and plane are on the same object, so this holds for every R.)
  bool projectsExactly() const;
};

}  // namespace relpos::manifolds::translation
