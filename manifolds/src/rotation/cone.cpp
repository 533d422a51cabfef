#include "cone.hpp"

#include "relpos/core/tolerance.hpp"

namespace relpos::manifolds::rotation::detail {

Vector3d coneAxis(const Vector3d& u_m, const Vector3d& u_f) {
  const Vector3d w = u_m.cross(u_f);
  const double s = w.norm();
  return s > kUnitRounding ? Vector3d(w / s) : anyPerpendicular(u_m);
}

Matrix3d coneBase(const Vector3d& u_m, const Vector3d& u_f, double alpha) {
  return axisAngle(coneAxis(u_m, u_f), angleBetween(u_m, u_f) - alpha);
}

}  // namespace relpos::manifolds::rotation::detail
