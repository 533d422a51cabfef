#include "relpos/manifolds/translation/point_of_line_plane.hpp"

namespace relpos::manifolds::translation {

Parameter PointOfLinePlane::parameter(int i) const {
  (void)i;
  return lengthParameter("lambda");  // no parameter: what an index past dof() has always given
}

Vector3d PointOfLinePlane::translation(const Matrix3d& R, const double* t) const {
  (void)t;
  const TShape s = shapeOf(line, R);
  return whereLineMeetsPlane(s.c, s.d, shapeOf(plane, R));
}

void PointOfLinePlane::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  (void)R, (void)T, (void)t;
}

}  // namespace relpos::manifolds::translation
