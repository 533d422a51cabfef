#include "relpos/manifolds/rotation/two_angle_range.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "cone.hpp"

namespace relpos::manifolds::rotation {
namespace {

// The rotation about c × d taking c to d (smooth for d away from −c: every d of one side, whose
// pole c is).
Matrix3d turnTo(const Vector3d& c, const Vector3d& d) {
  return Eigen::Quaterniond::FromTwoVectors(c, d).toRotationMatrix();
}

}  // namespace

TwoAngleRange::TwoAngleRange(const Vector3d& m_, const Vector3d& u1_, double a_lo_, double a_hi_,
                             const Vector3d& u2_, double b_lo_, double b_hi_, double side_)
    : m(m_.normalized()),
      u1(u1_.normalized()),
      u2(u2_.normalized()),
      a_lo(a_lo_),
      a_hi(a_hi_),
      b_lo(b_lo_),
      b_hi(b_hi_),
      side(side_ < 0.0 ? -1.0 : 1.0),
      sigma(angleBetween(u1, u2)) {
  e2 = (u2 - u2.dot(u1) * u1).normalized();
  e3 = u1.cross(e2);
  Rc = detail::coneBase(m, side * e3, 0.0);
  // The box is whole when both ends of the α range meet all of [b_lo, b_hi] (the bounds are
  // linear in α between them).
  fraction = false;
  for (double a : {a_lo, a_hi}) {
    double lo, hi;
    betaBounds(a, &lo, &hi);
    fraction = fraction || lo > b_lo || hi < b_hi;
  }
}

void TwoAngleRange::betaBounds(double alpha, double* lo, double* hi) const {
  *lo = std::max(b_lo, std::abs(alpha - sigma));
  *hi = std::min({b_hi, alpha + sigma, 2.0 * kPi - alpha - sigma});
}

void TwoAngleRange::alphaBounds(double* lo, double* hi) const {
  *lo = std::max({a_lo, b_lo - sigma, sigma - b_hi});
  *hi = std::min({a_hi, 2.0 * kPi - sigma - b_lo, sigma + b_hi});
}

bool TwoAngleRange::empty() const {
  double lo, hi;
  alphaBounds(&lo, &hi);
  if (lo > hi) return true;
  if (dof() == 3) return false;
  betaBounds(a_lo, &lo, &hi);
  return lo > hi;
}

Vector3d TwoAngleRange::direction(double alpha, double beta) const {
  // d = x u1 + y e2 + z e3: d·u1 = cos α, d·u2 = x cos σ + y sin σ = cos β.
  const double x = std::cos(alpha);
  const double y = (std::cos(beta) - x * std::cos(sigma)) / std::sin(sigma);
  const double z = side * std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  return (x * u1 + y * e2 + z * e3).normalized();
}

Parameter TwoAngleRange::parameter(int i) const {
  if (i == 1) return turnParameter("theta");
  if (dof() == 2) {
    double lo, hi;
    betaBounds(a_lo, &lo, &hi);
    return Parameter{"beta", ParamKind::kAngle, lo, hi, false};
  }
  if (i == 0) {
    double lo, hi;
    alphaBounds(&lo, &hi);
    return Parameter{"alpha", ParamKind::kAngle, lo, hi, false};
  }
  return fraction ? Parameter{"beta_fraction", ParamKind::kOther, 0.0, 1.0, false}
                  : Parameter{"beta", ParamKind::kAngle, b_lo, b_hi, false};
}

void TwoAngleRange::angles(const double* t, double* alpha, double* beta) const {
  if (dof() == 2) {
    *alpha = a_lo;
    *beta = t[0];
    return;
  }
  *alpha = t[0];
  if (!fraction) {
    *beta = t[2];
    return;
  }
  double lo, hi;
  betaBounds(*alpha, &lo, &hi);
  *beta = lo + t[2] * std::max(0.0, hi - lo);
}

Matrix3d TwoAngleRange::spinBase(const double* t) const {
  double alpha, beta;
  angles(t, &alpha, &beta);
  return turnTo(side * e3, direction(alpha, beta)) * Rc;
}

Matrix3d TwoAngleRange::rotation(const double* t) const {
  return spinBase(t) * axisAngle(m, t[1]);
}

void TwoAngleRange::project(const Matrix3d& R, double* t) const {
  // α and β of R m, each clamped to where it may be (a direction of the other side goes to its
  // mirror image), then the best spin about m.
  const Vector3d d = R * m;
  double alpha = a_lo;
  if (dof() == 3) {
    double lo, hi;
    alphaBounds(&lo, &hi);
    alpha = std::clamp(angleBetween(d, u1), lo, std::max(lo, hi));
  }
  double lo, hi;
  betaBounds(alpha, &lo, &hi);
  const double beta = std::clamp(angleBetween(d, u2), lo, std::max(lo, hi));
  if (dof() == 2) {
    t[0] = beta;
  } else {
    t[0] = alpha;
    t[2] = !fraction ? beta : (hi > lo ? std::clamp((beta - lo) / (hi - lo), 0.0, 1.0) : 0.5);
  }
  t[1] = bestSpinAbout(m, R.transpose() * spinBase(t));
}

}  // namespace relpos::manifolds::rotation
