#include "relpos/manifolds/translation/line.hpp"

namespace relpos::manifolds::translation {

Parameter Line::parameter(int i) const {
  (void)i;
  return lengthParameter("lambda");
}

Vector3d Line::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  return s.c + t[0] * s.d;
}

void Line::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(c, R);
  t[0] = (T - s.c).dot(s.d);
}

}  // namespace relpos::manifolds::translation
