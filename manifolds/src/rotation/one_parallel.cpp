#include "relpos/manifolds/rotation/one_parallel.hpp"

#include <cmath>

#include "cone.hpp"

namespace relpos::manifolds::rotation {

OneParallel::OneParallel(const Vector3d& u_m, const Vector3d& u_f)
    : u_m(u_m), u_f(u_f), R0(detail::coneBase(u_m, u_f, 0.0)) {}

Parameter OneParallel::parameter(int i) const {
  (void)i;
  return Parameter{"phi", ParamKind::kAngle, phi_lo, phi_hi, phi_periodic};
}

Matrix3d OneParallel::rotation(const double* t) const { return axisAngle(u_f, t[0]) * R0; }

void OneParallel::project(const Matrix3d& R, double* t) const {
  t[0] = bestSpinAbout(u_f, R0 * R.transpose());
  if (!phi_periodic) t[0] = ontoArc(t[0], phi_lo, phi_hi);
}

double ontoArc(double phi, double lo, double hi) {
  const double turn = 2.0 * kPi;
  const double from_lo = phi - lo - turn * std::floor((phi - lo) / turn);  // in [0, 2π)
  if (lo + from_lo <= hi) return lo + from_lo;
  // Past hi by from_lo − (hi − lo), short of lo (a turn on) by 2π − from_lo.
  return from_lo - (hi - lo) <= turn - from_lo ? hi : lo;
}

}  // namespace relpos::manifolds::rotation
