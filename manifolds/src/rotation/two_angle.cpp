#include "relpos/manifolds/rotation/two_angle.hpp"

#include <algorithm>
#include <cmath>

#include "relpos/manifolds/rotation/one_parallel.hpp"

namespace relpos::manifolds::rotation {

TwoAngle::TwoAngle(const OneAngle& first, const Vector3d& v_m, const Vector3d& v_f, double cos_beta)
    : u_m(first.u_m), u_f(first.u_f), R0(first.R0), v_m(v_m), v_f(v_f), cos_beta(cos_beta) {}

Parameter TwoAngle::parameter(int i) const {
  (void)i;
  return Parameter{"phi", ParamKind::kAngle, phi_lo, phi_hi, phi_periodic};
}

bool TwoAngle::theta(double phi, double* theta) const {
  // With R1 = R(u_f, φ) R0, solve (R(u_m, θ) v_m) . g = cos β for g = R1ᵀ v_f:
  // A cos θ + B sin θ = C (App. III-D, written in the mobile frame).
  Matrix3d R1 = axisAngle(u_f, phi) * R0;
  Vector3d g = R1.transpose() * v_f;
  double c = u_m.dot(v_m);
  Vector3d v_perp = v_m - c * u_m;
  double A = v_perp.dot(g);
  double B = u_m.cross(v_perp).dot(g);
  double C = cos_beta - c * u_m.dot(g);
  double rho = std::hypot(A, B);
  double ratio = rho > 0 ? C / rho : 2.0;
  bool ok = std::abs(ratio) <= 1.0 + kAngleRoundingFloor;
  *theta = std::atan2(B, A) + sign * std::acos(clampUnit(ratio));
  return ok;
}

Matrix3d TwoAngle::rotation(const double* t) const {
  double th = 0;
  theta(t[0], &th);
  return axisAngle(u_f, t[0]) * R0 * axisAngle(u_m, th);
}

void TwoAngle::project(const Matrix3d& R, double* t) const {
  // One-dimensional: the best of a fine deterministic scan, refined by golden section.
  auto cost = [&](double phi) {
    double th[1] = {phi};
    return rotationDistance(rotation(th), R);
  };
  const int n = 64;
  double best = phi_lo, best_c = cost(phi_lo);
  for (int k = 1; k <= n; ++k) {
    double phi = phi_lo + (phi_hi - phi_lo) * k / n;
    double c = cost(phi);
    if (c < best_c) best_c = c, best = phi;
  }
  // The first cone's φ for R (as OneAngle::project finds it): exactly R's φ when R is on the
  // branch, and near the projection beside it, where a minimum narrower than the scan's steps (φ
  // near an end of its range, or where θ(φ) turns steeply) lay between two of them and the scan
  // settled 0.5 rad away.
  double phi = coneAzimuth(u_m, u_f, R0, R);
  if (!std::isnan(phi)) {
    // (On a range beyond ±π, [0.28, 6.54], the same azimuth a whole turn on.)
    if (!phi_periodic) phi = ontoArc(phi, phi_lo, phi_hi);
    const double c = cost(phi);
    if (c < best_c) best_c = c, best = phi;
  }
  // Golden sections over the scan's steps about the best; over a periodic range across its ends
  // too (the best just past -π is as near +π, and the scan may find either).
  double h = (phi_hi - phi_lo) / n;
  double a = best - h, b = best + h;
  if (!phi_periodic) a = std::max(phi_lo, a), b = std::min(phi_hi, b);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (cost(x1) < cost(x2))
      b = x2;
    else
      a = x1;
  }
  double m = 0.5 * (a + b);
  if (phi_periodic) m = std::remainder(m, 2 * kPi);
  t[0] = cost(m) < best_c ? m : best;
}

}  // namespace relpos::manifolds::rotation
