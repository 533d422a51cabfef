#include "relpos/manifolds/translation/sphere.hpp"

#include <cmath>

namespace relpos::manifolds::translation {

Parameter Sphere::parameter(int i) const { return i == 1 ? polarParameter() : azimuthParameter(); }

Vector3d Sphere::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  return s.c + s.r * Vector3d(std::cos(t[0]) * std::sin(t[1]), std::sin(t[0]) * std::sin(t[1]),
                              std::cos(t[1]));
}

void Sphere::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const Vector3d v = T - shapeOf(c, R).c;
  if (v.norm() < kDivisionGuard) {
    t[0] = t[1] = 0.0;
  } else {
    t[0] = std::atan2(v.y(), v.x());
    t[1] = std::acos(clampUnit(v.z() / v.norm()));
  }
}

}  // namespace relpos::manifolds::translation
