#include "relpos/manifolds/translation/ellipse.hpp"

#include <cmath>

#include "relpos/core/geometry.hpp"

namespace relpos::manifolds::translation {
namespace {

// The two in-plane axes of the ellipse cut by a cylinder (axis d, radius r) from a plane
// (normal n): e1 ⊥ d and n, e2 = n × e1, semi-axes r and r / |d·n| (PMF eq. 10).
// The cross product is the accurate one: where the axis is nearly normal to the plane (a near
// circle), n × d is tiny and its plain rounding, normalised, would tilt e1 out of the plane by
// rounding / |n × d| and lift the whole ellipse off it (7e-7 at |n × d| = 1.7e-11).
void ellipseAxes(const TShape& cyl, const TShape& plane, Vector3d* e1, Vector3d* e2, double* b) {
  const Vector3d w = accurateCross(plane.d, cyl.d);
  *e1 = w.norm() > kUnitRounding ? Vector3d(w.normalized()) : cyl.e1;
  *e2 = plane.d.cross(*e1);
  *b = cyl.r / std::abs(cyl.d.dot(plane.d));
}

}  // namespace

Parameter Ellipse::parameter(int i) const {
  (void)i;
  return azimuthParameter();
}

Vector3d Ellipse::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(cylinder, R);
  const TShape pl = shapeOf(plane, R);
  Vector3d a1, a2;
  double b;
  ellipseAxes(s, pl, &a1, &a2, &b);
  return whereLineMeetsPlane(s.c, s.d, pl) + s.r * std::cos(t[0]) * a1 + b * std::sin(t[0]) * a2;
}

void Ellipse::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(cylinder, R);
  const TShape pl = shapeOf(plane, R);
  Vector3d a1, a2;
  double b;
  ellipseAxes(s, pl, &a1, &a2, &b);
  Vector3d w = T - whereLineMeetsPlane(s.c, s.d, pl);
  t[0] = std::atan2(w.dot(a2) / b, w.dot(a1) / s.r);
}

}  // namespace relpos::manifolds::translation
