#include "relpos/manifolds/translation/thick_cylinder.hpp"

#include <cmath>

namespace relpos::manifolds::translation {

Parameter ThickCylinder::parameter(int i) const {
  return i == 0 ? lengthParameter("lambda") : (i == 1 ? azimuthParameter() : rangeParameter(c));
}

Vector3d ThickCylinder::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  return s.c + t[0] * s.d + t[2] * (std::cos(t[1]) * s.e1 + std::sin(t[1]) * e2);
}

void ThickCylinder::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  const Vector3d v = T - s.c;
  t[0] = v.dot(s.d);
  const Vector3d perp = v - t[0] * s.d;
  t[1] = std::atan2(perp.dot(e2), perp.dot(s.e1));
  t[2] = clampToRange(c, perp.norm());
}

}  // namespace relpos::manifolds::translation
