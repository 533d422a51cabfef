#include "relpos/manifolds/translation/line_of_planes.hpp"

namespace relpos::manifolds::translation {
namespace {

// The planes' line for R: its point nearest the first plane's point, its unit direction.
void planesLine(const LineOfPlanes& s, const Matrix3d& R, Vector3d* point, Vector3d* dir) {
  const TShape a = shapeOf(s.first, R), b = shapeOf(s.second, R);
  *point = pointWherePlanesMeet(a.c, a.d, b.c, b.d);
  *dir = accurateCross(a.d, b.d).normalized();
}

}  // namespace

Parameter LineOfPlanes::parameter(int i) const {
  (void)i;
  return lengthParameter("lambda");
}

Vector3d LineOfPlanes::translation(const Matrix3d& R, const double* t) const {
  Vector3d p, d;
  planesLine(*this, R, &p, &d);
  return p + t[0] * d;
}

void LineOfPlanes::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  Vector3d p, d;
  planesLine(*this, R, &p, &d);
  t[0] = (T - p).dot(d);
}

}  // namespace relpos::manifolds::translation
