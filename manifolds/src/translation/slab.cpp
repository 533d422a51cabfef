#include "relpos/manifolds/translation/slab.hpp"

namespace relpos::manifolds::translation {
namespace {

// T = S_f − R S_m: a mobile point on a fixed plane moves with +n, a fixed point on a mobile
// plane puts T on the −n side.
double slabSign(const Fundamental& f) { return f.point_side == Side::kMobile ? 1.0 : -1.0; }

}  // namespace

Parameter Slab::parameter(int i) const {
  if (i == 2) return rangeParameter(c);
  return lengthParameter(i == 0 ? "lambda1" : "lambda2");
}

Vector3d Slab::translation(const Matrix3d& R, const double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  return s.c + t[0] * s.e1 + t[1] * e2 + slabSign(c) * t[2] * s.d;
}

void Slab::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape s = shapeOf(c, R);
  const Vector3d e2 = s.d.cross(s.e1);
  const Vector3d v = T - s.c;
  t[0] = v.dot(s.e1);
  t[1] = v.dot(e2);
  t[2] = clampToRange(c, slabSign(c) * v.dot(s.d));
}

}  // namespace relpos::manifolds::translation
