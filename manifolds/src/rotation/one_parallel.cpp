#include "relpos/manifolds/rotation/one_parallel.hpp"

#include "cone.hpp"

namespace relpos::manifolds::rotation {

OneParallel::OneParallel(const Vector3d& u_m, const Vector3d& u_f)
    : u_m(u_m), u_f(u_f), R0(detail::coneBase(u_m, u_f, 0.0)) {}

Parameter OneParallel::parameter(int i) const {
  (void)i;
  return turnParameter("phi");
}

Matrix3d OneParallel::rotation(const double* t) const { return axisAngle(u_f, t[0]) * R0; }

void OneParallel::project(const Matrix3d& R, double* t) const {
  t[0] = bestSpinAbout(u_f, R0 * R.transpose());
}

}  // namespace relpos::manifolds::rotation
