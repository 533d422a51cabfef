#include "relpos/manifolds/translation/cylinder.hpp"

#include <cmath>

namespace relpos::manifolds::translation {

Parameter Cylinder::parameter(int i) const {
  return i == 0 ? lengthParameter("lambda") : azimuthParameter();
}

Vector3d Cylinder::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  return s.c + t[0] * s.d + s.r * (std::cos(t[1]) * s.e1 + std::sin(t[1]) * e2);
}

void Cylinder::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  const Vector3d v = T - s.c;
  t[0] = v.dot(s.d);
  t[1] = std::atan2(v.dot(e2), v.dot(s.e1));
}

}  // namespace relpos::manifolds::translation
