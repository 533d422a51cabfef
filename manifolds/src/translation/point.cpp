#include "relpos/manifolds/translation/point.hpp"

namespace relpos::manifolds::translation {

Parameter Point::parameter(int i) const {
  (void)i;
  return lengthParameter("lambda");  // no parameter: what an index past dof() has always given
}

Vector3d Point::translation(const Matrix3d& R, const double* t) const {
  (void)t;
  return shapeOf(c, R).c;
}

void Point::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  (void)R, (void)T, (void)t;
}

}  // namespace relpos::manifolds::translation
