#include "relpos/manifolds/rotation/fixed.hpp"

namespace relpos::manifolds::rotation {

Fixed::Fixed(const Matrix3d& R) : R0(Quaterniond(R).normalized().toRotationMatrix()) {}

Parameter Fixed::parameter(int i) const {
  (void)i;
  return turnParameter("");  // no parameter: what a parameter index past dof() has always given
}

Matrix3d Fixed::rotation(const double* theta) const {
  (void)theta;
  return R0;
}

void Fixed::project(const Matrix3d& R, double* theta) const {
  (void)R;
  (void)theta;
}

}  // namespace relpos::manifolds::rotation
