#include "relpos/manifolds/translation/free.hpp"

namespace relpos::manifolds::translation {

Parameter Free::parameter(int i) const {
  return lengthParameter(i == 0 ? "x" : (i == 1 ? "y" : "z"));
}

Vector3d Free::translation(const Matrix3d& R, const double* t) const {
  (void)R;
  return Vector3d(t[0], t[1], t[2]);
}

void Free::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  (void)R;
  t[0] = T.x(), t[1] = T.y(), t[2] = T.z();
}

}  // namespace relpos::manifolds::translation
