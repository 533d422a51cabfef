#include "relpos/manifolds/translation/shell.hpp"

#include <cmath>

namespace relpos::manifolds::translation {

Parameter Shell::parameter(int i) const {
  if (i == 2) return rangeParameter(c);
  return i == 1 ? polarParameter() : azimuthParameter();
}

Vector3d Shell::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  return s.c + t[2] * Vector3d(std::cos(t[0]) * std::sin(t[1]), std::sin(t[0]) * std::sin(t[1]),
                               std::cos(t[1]));
}

void Shell::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const Vector3d v = T - shapeOf(c, R).c;
  const double r = v.norm();
  t[0] = r > kDivisionGuard ? std::atan2(v.y(), v.x()) : 0.0;
  t[1] = r > kDivisionGuard ? std::acos(clampUnit(v.z() / r)) : 0.0;
  t[2] = clampToRange(c, r);
}

}  // namespace relpos::manifolds::translation
