#include "relpos/core/fundamental.hpp"

namespace relpos {

const char* toString(FundamentalKind k) {
  switch (k) {
    case FundamentalKind::kPointPoint:
      return "point-point";
    case FundamentalKind::kPointLine:
      return "point-line";
    case FundamentalKind::kPointPlane:
      return "point-plane";
    case FundamentalKind::kAngle:
      return "angle";
    case FundamentalKind::kLineLine:
      return "line-line";
    case FundamentalKind::kCustom:
      return "custom";
  }
  return "?";
}

Fundamental Fundamental::lineLine(const Vector3d& a_m, const Vector3d& u_m, const Vector3d& a_f,
                                  const Vector3d& d_f, double lo, double hi, SourceMask s) {
  Fundamental f;
  f.kind = FundamentalKind::kLineLine;
  f.point_side = Side::kMobile;
  f.p = a_m;
  f.u = u_m.normalized();
  f.q = a_f;
  f.d = d_f.normalized();
  f.lo = lo;
  f.hi = hi;
  f.sources = s;
  return f;
}

Fundamental Fundamental::pointPoint(const Vector3d& p_m, const Vector3d& q_f, double v,
                                    SourceMask s) {
  Fundamental f;
  f.kind = FundamentalKind::kPointPoint;
  f.point_side = Side::kMobile;
  f.p = p_m;
  f.q = q_f;
  f.lo = f.hi = v;
  f.sources = s;
  return f;
}

Fundamental Fundamental::pointLine(Side point_side, const Vector3d& p, const Vector3d& a,
                                   const Vector3d& d, double v, SourceMask s) {
  Fundamental f;
  f.kind = FundamentalKind::kPointLine;
  f.point_side = point_side;
  f.p = p;
  f.q = a;
  f.d = d.normalized();
  f.lo = f.hi = v;
  f.sources = s;
  return f;
}

Fundamental Fundamental::pointPlane(Side point_side, const Vector3d& p, const Vector3d& a,
                                    const Vector3d& n, double v, SourceMask s) {
  Fundamental f;
  f.kind = FundamentalKind::kPointPlane;
  f.point_side = point_side;
  f.p = p;
  f.d = n.normalized();
  // (p - a).n = v  <=>  (p - (a + v n)).n = 0: keep every exact point-plane a coincidence
  // (PMF Table I, first row: d(P, Π) = p becomes d(P, Υ) = 0).
  f.q = a + v * f.d;
  f.lo = f.hi = 0.0;
  f.sources = s;
  return f;
}

Fundamental Fundamental::angle(const Vector3d& u_m, const Vector3d& u_f, double alpha,
                               SourceMask s) {
  Fundamental f;
  f.kind = FundamentalKind::kAngle;
  f.p = u_m.normalized();
  f.q = u_f.normalized();
  f.lo = f.hi = alpha;
  f.sources = s;
  return f;
}

Vector3d* Fundamental::fixedPoint() {
  switch (kind) {
    case FundamentalKind::kPointPoint:
    case FundamentalKind::kLineLine:
      return &q;
    case FundamentalKind::kPointLine:
    case FundamentalKind::kPointPlane:
      return point_side == Side::kFixed ? &p : &q;
    case FundamentalKind::kAngle:
    case FundamentalKind::kCustom:
      break;
  }
  return nullptr;
}

Vector3d* Fundamental::mobilePoint() {
  switch (kind) {
    case FundamentalKind::kPointPoint:
    case FundamentalKind::kLineLine:
      return &p;
    case FundamentalKind::kPointLine:
    case FundamentalKind::kPointPlane:
      return point_side == Side::kMobile ? &p : &q;
    case FundamentalKind::kAngle:
    case FundamentalKind::kCustom:
      break;
  }
  return nullptr;
}

void Fundamental::translate(const Vector3d& offset_W, const Vector3d& offset_M) {
  if (Vector3d* f = fixedPoint()) *f += offset_W;
  if (Vector3d* m = mobilePoint()) *m += offset_M;
}

SourceMask ConstraintSet::usedSources() const {
  SourceMask m = 0;
  for (const auto& f : translational) m |= f.sources;
  for (const auto& f : rotational) m |= f.sources;
  return m;
}

}  // namespace relpos
