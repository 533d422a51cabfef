#pragma once
// A circle (issue 16): two translational constraints on different mobile points whose shapes in
// translation space — a sphere and a sphere, or a sphere and a plane — meet for the rotations the
// matcher keeps (an implicit angle range on the vector between the points, separable_matcher.cpp).
// For a rotation R the circle is their intersection; the parameter is the azimuth about its axis
// (the line of centres, or the plane's normal).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Circle : ShapeBase<Circle> {
  static constexpr const char* kName = "Circle";
  static constexpr const char* kSummary =
      "1 DOF: two distances (or a distance and a plane) on two mobile points, for each rotation";
  // sphere: a point-point distance > 0; other: a point-point distance > 0 or a mobile point on a
  // fixed plane, on another mobile point.
  Circle(const Fundamental& sphere_, const Fundamental& other_) : sphere(sphere_), other(other_) {}
  Fundamental sphere, other;
  // Circles no larger than this are their centre: where the shapes touch, rounding leaves a
  // radius of about √(2 r ε) for an ε-error in where they meet; the centre then breaks the
  // sphere by r − √(r² − ρ²) ≈ ρ² / 2r, within the tolerance the matcher derived this from.
  double snap_radius = 0.0;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.sphere);
    fn(self.other);
  }

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;

 private:
  // The circle at R: centre, radius and an orthonormal frame (axis, e1, e2).
  void frame(const Matrix3d& R, Vector3d* centre, double* radius, Vector3d* e1,
             Vector3d* e2) const;
};

}  // namespace relpos::manifolds::translation
