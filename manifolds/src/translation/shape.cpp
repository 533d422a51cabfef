#include "relpos/manifolds/translation/shape.hpp"

#include <limits>

namespace relpos::manifolds {

TShape shapeOf(const Fundamental& f, const Matrix3d& R) {
  // Mobile point p, fixed element (q, d):  R p + T ∈ X      =>  T ∈ X − R p.
  // Fixed point p, mobile element (q, d):  p ∈ R X + T      =>  T ∈ p − R X (direction R d).
  TShape s;
  const bool point_mobile = f.point_side == Side::kMobile;
  const Vector3d c = point_mobile ? Vector3d(f.q - R * f.p) : Vector3d(f.p - R * f.q);
  s.c = c;
  s.d = point_mobile ? f.d : Vector3d(R * f.d);
  s.e1 = point_mobile ? anyPerpendicular(f.d) : Vector3d(R * anyPerpendicular(f.d));
  s.r = f.value();
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      s.kind = s.r == 0.0 ? TShape::kPoint : TShape::kSphere;
      break;
    case FundamentalKind::kPointLine:
      s.kind = s.r == 0.0 ? TShape::kLine : TShape::kCylinder;
      break;
    case FundamentalKind::kPointPlane:
      s.kind = TShape::kPlane;
      break;
    case FundamentalKind::kAngle:
    case FundamentalKind::kLineLine:
    case FundamentalKind::kCustom:
      break;
  }
  return s;
}

void planeOf(const Fundamental& f, const Matrix3d& R, Vector3d* c, Vector3d* n) {
  const bool point_mobile = f.point_side == Side::kMobile;
  *c = point_mobile ? Vector3d(f.q - R * f.p) : Vector3d(f.p - R * f.q);
  *n = point_mobile ? f.d : Vector3d(R * f.d);
}

Vector3d whereLineMeetsPlane(const Vector3d& c, const Vector3d& d, const TShape& plane) {
  return c + ((plane.c - c).dot(plane.d) / d.dot(plane.d)) * d;
}

namespace {

// Within rounding of an exact zero, relative to the vector's length: a feature off the axis by
// more than that moves with the spin, and the spin is then searched like any parameter.
bool alongAxis(const Vector3d& v, const Vector3d& u) {
  return v.cross(u).norm() <= kUnitRounding * (1.0 + v.norm());
}

}  // namespace

bool mobileGeometryInvariant(const Fundamental& f, const Vector3d& u) {
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      return alongAxis(f.p, u);  // stored with the point mobile
    case FundamentalKind::kPointLine:
      return f.point_side == Side::kMobile ? alongAxis(f.p, u)
                                           : alongAxis(f.d, u) && alongAxis(f.q, u);
    case FundamentalKind::kPointPlane:
      return f.point_side == Side::kMobile ? alongAxis(f.p, u) : alongAxis(f.d, u);
    default:
      return false;  // not a point-based translational constraint: no claim
  }
}

bool mobilePointAtOrigin(const Fundamental& f) {
  const Vector3d* p = mobileConstraintPoint(f);
  return p && *p == Vector3d::Zero();
}

const Vector3d* mobileConstraintPoint(const Fundamental& f) {
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
    case FundamentalKind::kPointLine:
    case FundamentalKind::kPointPlane:
      return f.point_side == Side::kMobile ? &f.p : nullptr;
    default:
      return nullptr;
  }
}

namespace translation {

Parameter lengthParameter(const char* name) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return Parameter{name, ParamKind::kLength, -inf, inf, false};
}
Parameter azimuthParameter() { return Parameter{"alpha", ParamKind::kAngle, -kPi, kPi, true}; }
Parameter polarParameter() { return Parameter{"beta", ParamKind::kAngle, 0.0, kPi, false}; }
Parameter rangeParameter(const Fundamental& f) {
  return Parameter{"distance", ParamKind::kLength, f.lo, f.hi, false};
}

}  // namespace translation
}  // namespace relpos::manifolds
