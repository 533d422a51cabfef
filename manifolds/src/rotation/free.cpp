#include "relpos/manifolds/rotation/free.hpp"

#include <cmath>

namespace relpos::manifolds::rotation {

Parameter Free::parameter(int i) const {
  if (i == 1) return Parameter{"pitch", ParamKind::kAngle, -kPi / 2, kPi / 2, false};
  return turnParameter(i == 0 ? "roll" : "yaw");
}

Matrix3d Free::rotation(const double* t) const {
  return axisAngle(Vector3d::UnitZ(), t[2]) * axisAngle(Vector3d::UnitY(), t[1]) *
         axisAngle(Vector3d::UnitX(), t[0]);
}

void Free::project(const Matrix3d& R, double* t) const {
  double sp = -R(2, 0);
  t[1] = std::asin(clampUnit(sp));
  if (std::abs(sp) < 1.0 - kUnitRounding) {
    t[0] = std::atan2(R(2, 1), R(2, 2));
    t[2] = std::atan2(R(1, 0), R(0, 0));
  } else {  // gimbal lock: roll and yaw share one axis; put it all in yaw
    t[0] = 0.0;
    t[2] = std::atan2(-R(0, 1), R(1, 1));
  }
}

}  // namespace relpos::manifolds::rotation
