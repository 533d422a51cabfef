#include "relpos/manifolds/rotation/one_angle_range.hpp"

#include <algorithm>

#include "cone.hpp"
#include "relpos/manifolds/rotation/one_angle.hpp"

namespace relpos::manifolds::rotation {

OneAngleRange::OneAngleRange(const Vector3d& u_m, const Vector3d& u_f, double lo, double hi)
    : u_m(u_m),
      u_f(u_f),
      alpha_lo(lo),
      alpha_hi(hi),
      cone_axis(detail::coneAxis(u_m, u_f)),
      cone_beta(angleBetween(u_m, u_f)) {}

Parameter OneAngleRange::parameter(int i) const {
  if (i == 2) return Parameter{"alpha", ParamKind::kAngle, alpha_lo, alpha_hi, false};
  return turnParameter(i == 0 ? "phi" : "theta");
}

Matrix3d OneAngleRange::rotation(const double* t) const {
  return spinBase(t) * axisAngle(u_m, t[1]);
}

Matrix3d OneAngleRange::spinBase(const double* t) const {
  return axisAngle(u_f, t[0]) * axisAngle(cone_axis, cone_beta - t[2]);
}

void OneAngleRange::project(const Matrix3d& R, double* t) const {
  // α: the angle of R u_m from u_f, clamped to the range; then as for one angle.
  const double a = std::min(alpha_hi, std::max(alpha_lo, angleBetween(R * u_m, u_f)));
  OneAngle(u_m, u_f, a).project(R, t);
  t[2] = a;
}

}  // namespace relpos::manifolds::rotation
