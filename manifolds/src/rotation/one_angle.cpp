#include "relpos/manifolds/rotation/one_angle.hpp"

#include <cmath>
#include <limits>

#include "cone.hpp"

namespace relpos::manifolds::rotation {

OneAngle::OneAngle(const Vector3d& u_m, const Vector3d& u_f, double alpha)
    : u_m(u_m), u_f(u_f), R0(detail::coneBase(u_m, u_f, alpha)) {}

Parameter OneAngle::parameter(int i) const { return turnParameter(i == 0 ? "phi" : "theta"); }

Matrix3d OneAngle::rotation(const double* t) const {
  return axisAngle(u_f, t[0]) * R0 * axisAngle(u_m, t[1]);
}

double coneAzimuth(const Vector3d& u_m, const Vector3d& u_f, const Matrix3d& R0,
                   const Matrix3d& R) {
  const Vector3d w0 = R0 * u_m, x = R * u_m;
  const Vector3d w0p = w0 - w0.dot(u_f) * u_f, xp = x - x.dot(u_f) * u_f;
  if (xp.norm() < kUnitRounding || w0p.norm() < kUnitRounding)
    return std::numeric_limits<double>::quiet_NaN();
  return std::atan2(w0p.cross(xp).dot(u_f), w0p.dot(xp));
}

Matrix3d OneAngle::spinBase(const double* t) const { return axisAngle(u_f, t[0]) * R0; }

void OneAngle::project(const Matrix3d& R, double* t) const {
  // φ puts R0 u_m at the azimuth (about u_f) of R u_m, then θ is the best spin about u_m.
  const double phi = coneAzimuth(u_m, u_f, R0, R);
  t[0] = std::isnan(phi) ? 0.0 : phi;
  Matrix3d R1 = axisAngle(u_f, t[0]) * R0;
  t[1] = bestSpinAbout(u_m, R.transpose() * R1);
}

}  // namespace relpos::manifolds::rotation
