#include "relpos/manifolds/rotation/angle_with_range.hpp"

#include <algorithm>
#include <cmath>

#include "cone.hpp"
#include "relpos/manifolds/rotation/one_angle.hpp"
#include "relpos/manifolds/rotation/one_parallel.hpp"

namespace relpos::manifolds::rotation {

AngleWithRange::AngleWithRange(const Vector3d& u_m_, const Vector3d& u_f_, double alpha,
                               const Vector3d& v_m_, const Vector3d& v_f_, double lo, double hi)
    : u_m(u_m_),
      u_f(u_f_),
      v_m(v_m_),
      v_f(v_f_),
      R0(detail::coneBase(u_m_, u_f_, alpha)),
      cos_lo(std::cos(lo)),
      cos_hi(std::cos(hi)) {}

Parameter AngleWithRange::parameter(int i) const {
  if (i == 0) return Parameter{"phi", ParamKind::kAngle, phi_lo, phi_hi, phi_periodic};
  return Parameter{"theta_fraction", ParamKind::kOther, 0.0, 1.0, false};
}

void AngleWithRange::arc(double phi, double* theta0, double* psi_in, double* psi_out) const {
  // R(u_m, θ) v_m · z, z = (R(u_f, φ) R0)ᵀ v_f: h + amp cos(θ − θ0).
  const Vector3d z = (axisAngle(u_f, phi) * R0).transpose() * v_f;
  const Vector3d vm_perp = v_m - v_m.dot(u_m) * u_m, z_perp = z - z.dot(u_m) * u_m;
  const double h = v_m.dot(u_m) * z.dot(u_m), amp = vm_perp.norm() * z_perp.norm();
  *theta0 = std::atan2(vm_perp.cross(z_perp).dot(u_m), vm_perp.dot(z_perp));
  if (!(amp > kUnitRounding)) {  // the spin does not move the angle: the whole turn
    *psi_in = 0.0;
    *psi_out = kPi;
    return;
  }
  *psi_in = std::acos(clampUnit((cos_lo - h) / amp));
  *psi_out = std::max(*psi_in, std::acos(clampUnit((cos_hi - h) / amp)));
}

Matrix3d AngleWithRange::rotation(const double* t) const {
  double theta0, in, out;
  arc(t[0], &theta0, &in, &out);
  const double theta = theta0 + sign * (in + t[1] * (out - in));
  return axisAngle(u_f, t[0]) * R0 * axisAngle(u_m, theta);
}

void AngleWithRange::project(const Matrix3d& R, double* t) const {
  // As for one angle, then φ onto its interval and θ onto this sign's arc.
  double cone[2];
  OneAngle one(u_m, u_f, 0.0);
  one.R0 = R0;
  one.project(R, cone);
  t[0] = phi_periodic ? cone[0] : ontoArc(cone[0], phi_lo, phi_hi);
  const double theta = bestSpinAbout(u_m, R.transpose() * axisAngle(u_f, t[0]) * R0);
  double theta0, in, out;
  arc(t[0], &theta0, &in, &out);
  double psi = sign * (theta - theta0);
  psi = std::remainder(psi, 2.0 * kPi);  // in [−π, π]
  t[1] = out > in ? std::clamp((psi - in) / (out - in), 0.0, 1.0) : 0.0;
}

}  // namespace relpos::manifolds::rotation
