#include "relpos/manifolds/translation/circle.hpp"

#include <algorithm>
#include <cmath>

namespace relpos::manifolds::translation {

Parameter Circle::parameter(int i) const {
  (void)i;
  return azimuthParameter();
}

void Circle::frame(const Matrix3d& R, Vector3d* centre, double* radius, Vector3d* e1,
                   Vector3d* e2) const {
  const TShape s = shapeOf(sphere, R), o = shapeOf(other, R);
  Vector3d axis;
  double along;  // from the sphere's centre to the circle's plane, along the axis
  if (o.kind == TShape::kPlane) {
    axis = o.d;
    along = (o.c - s.c).dot(axis);
  } else {
    const Vector3d u = o.c - s.c;
    const double D = u.norm();
    axis = D > 0.0 ? Vector3d(u / D) : Vector3d::UnitZ();
    along = D > 0.0 ? (s.r * s.r - o.r * o.r + D * D) / (2.0 * D) : 0.0;
  }
  *centre = s.c + along * axis;
  const double squared = s.r * s.r - along * along;
  *radius = squared > snap_radius * snap_radius ? std::sqrt(squared) : 0.0;
  *e1 = anyPerpendicular(axis);
  *e2 = axis.cross(*e1);
}

Vector3d Circle::translation(const Matrix3d& R, const double* t) const {
  Vector3d centre, e1, e2;
  double radius;
  frame(R, &centre, &radius, &e1, &e2);
  return centre + radius * (std::cos(t[0]) * e1 + std::sin(t[0]) * e2);
}

void Circle::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  Vector3d centre, e1, e2;
  double radius;
  frame(R, &centre, &radius, &e1, &e2);
  const Vector3d w = T - centre;
  t[0] = std::atan2(w.dot(e2), w.dot(e1));
}

}  // namespace relpos::manifolds::translation
