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

namespace {

// The cylinder and the plane placed for the rotation R, and the frame about the axis.
struct Placed {
  TShape cyl;
  Vector3d pc, pn, e2;
};

Placed placeFor(const BoundedCylinder& b, const Matrix3d& R) {
  Placed p{shapeOf(b.cylinder, R), Vector3d(), Vector3d(), Vector3d()};
  planeOf(b.plane, R, &p.pc, &p.pn);
  p.e2 = p.cyl.d.cross(p.cyl.e1);
  return p;
}

// Out from the axis along the unit vector u, by r, then along the axis onto the plane n·T = h (an
// oblique plane cuts the thick cylinder obliquely: Somani's oblique cylinder).
Vector3d placeAt(const BoundedCylinder& b, const Placed& at, const Vector3d& u, double r,
                 const double* t) {
  const Fundamental &cylinder = b.cylinder, &plane = b.plane;
  const double v = plane.exact() ? 0.0 : t[cylinder.exact() ? 1 : 2];
  const double sign = plane.point_side == Side::kMobile ? 1.0 : -1.0;
  const double h = at.pn.dot(at.pc) + sign * v;
  const double s = (h - at.pn.dot(at.cyl.c) - r * at.pn.dot(u)) / at.pn.dot(at.cyl.d);
  return at.cyl.c + s * at.cyl.d + r * u;
}

// The azimuth of T about the axis, its radius and its height clamped to the ranges; `u`: the
// azimuth's unit vector, from T's own components (cos and sin of the angle cost a sincos).
void projectOnto(const BoundedCylinder& b, const Placed& at, const Vector3d& T, double* t,
                 Vector3d* u) {
  const Fundamental &cylinder = b.cylinder, &plane = b.plane;
  const Vector3d w = T - at.cyl.c;
  const Vector3d perp = w - w.dot(at.cyl.d) * at.cyl.d;
  const double x = perp.dot(at.cyl.e1), y = perp.dot(at.e2);
  t[0] = std::atan2(y, x);
  // perp = x e1 + y e2 (it is square to the axis). On the axis the azimuth is atan2's for
  // (±0, ±0): 0 or π.
  const double rho = perp.norm();
  *u = rho > 0.0 ? Vector3d((x / rho) * at.cyl.e1 + (y / rho) * at.e2)
                 : Vector3d(std::cos(t[0]) * at.cyl.e1 + std::sin(t[0]) * at.e2);
  int k = 1;
  if (!cylinder.exact()) t[k++] = std::min(cylinder.hi, std::max(cylinder.lo, rho));
  if (!plane.exact()) {
    const double sign = plane.point_side == Side::kMobile ? 1.0 : -1.0;
    t[k] = std::min(plane.hi, std::max(plane.lo, sign * (at.pn.dot(T) - at.pn.dot(at.pc))));
  }
}

}  // namespace

Vector3d BoundedCylinder::translation(const Matrix3d& R, const double* t) const {
  const Placed at = placeFor(*this, R);
  const double r = cylinder.exact() ? cylinder.value() : t[1];
  return placeAt(*this, at, std::cos(t[0]) * at.cyl.e1 + std::sin(t[0]) * at.e2, r, t);
}

void BoundedCylinder::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  Vector3d u;
  projectOnto(*this, placeFor(*this, R), T, t, &u);
}

Vector3d BoundedCylinder::projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const {
  const Placed at = placeFor(*this, R);
  Vector3d u;
  projectOnto(*this, at, T, t, &u);
  return placeAt(*this, at, u, cylinder.exact() ? cylinder.value() : t[1], t);
}

}  // namespace relpos::manifolds::translation
