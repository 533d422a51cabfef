#include "relpos/manifolds/translation/plane.hpp"

namespace relpos::manifolds::translation {

Parameter Plane::parameter(int i) const { return lengthParameter(i == 0 ? "lambda1" : "lambda2"); }

Vector3d Plane::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  return s.c + t[0] * s.e1 + t[1] * e2;
}

void Plane::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  const Vector3d v = T - s.c;
  t[0] = v.dot(s.e1), t[1] = v.dot(e2);
}

}  // namespace relpos::manifolds::translation
