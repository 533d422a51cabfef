#include "relpos/manifolds/translation/bounded_cylinder.hpp"

#include <algorithm>
#include <cmath>

namespace relpos::manifolds::translation {

Parameter BoundedCylinder::parameter(int i) const {
  if (i == 0) return azimuthParameter();
  if (i == 1 && !cylinder.exact())
    return Parameter{"radius", ParamKind::kLength, cylinder.lo, cylinder.hi, false};
  return Parameter{"height", ParamKind::kLength, plane.lo, plane.hi, false};
}

bool BoundedCylinder::projectsExactly() const {
  const Matrix3d I = Matrix3d::Identity();
  return shapeOf(cylinder, I).d.cross(shapeOf(plane, I).d).norm() < kUnitRounding;
}

Vector3d BoundedCylinder::translation(const Matrix3d& R, const double* t) const {
  const TShape cyl = shapeOf(cylinder, R);
  Vector3d pc, pn;
  planeOf(plane, R, &pc, &pn);
  const double r = cylinder.exact() ? cylinder.value() : t[1];
  const double v = plane.exact() ? 0.0 : t[cylinder.exact() ? 1 : 2];
  const double sign = plane.point_side == Side::kMobile ? 1.0 : -1.0;
  const double h = pn.dot(pc) + sign * v;  // the plane n·T = h
  // Out from the axis along the azimuth, then along the axis onto the plane (an oblique plane
  // cuts the thick cylinder obliquely: Somani's oblique cylinder).
  const Vector3d u = std::cos(t[0]) * cyl.e1 + std::sin(t[0]) * cyl.d.cross(cyl.e1);
  const double s = (h - pn.dot(cyl.c) - r * pn.dot(u)) / pn.dot(cyl.d);
  return cyl.c + s * cyl.d + r * u;
}

void BoundedCylinder::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  const TShape cyl = shapeOf(cylinder, R);
  Vector3d pc, pn;
  planeOf(plane, R, &pc, &pn);
  const Vector3d w = T - cyl.c;
  const double along = w.dot(cyl.d);
  const Vector3d perp = w - along * cyl.d;
  const Vector3d e2 = cyl.d.cross(cyl.e1);
  t[0] = std::atan2(perp.dot(e2), perp.dot(cyl.e1));
  int k = 1;
  if (!cylinder.exact()) t[k++] = std::min(cylinder.hi, std::max(cylinder.lo, perp.norm()));
  if (!plane.exact()) {
    const double sign = plane.point_side == Side::kMobile ? 1.0 : -1.0;
    t[k] = std::min(plane.hi, std::max(plane.lo, sign * (pn.dot(T) - pn.dot(pc))));
  }
}

}  // namespace relpos::manifolds::translation
