#include "relpos/manifolds/translation_part.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relpos::manifolds {

const char* toString(TranslationKind k) {
  switch (k) {
    case TranslationKind::kFree:
      return "R3";
    case TranslationKind::kPoint:
      return "Point";
    case TranslationKind::kLine:
      return "Line";
    case TranslationKind::kPlane:
      return "Plane";
    case TranslationKind::kSphere:
      return "Sphere";
    case TranslationKind::kCylinder:
      return "Cylinder";
    case TranslationKind::kLineOfPlanes:
      return "Line";
    case TranslationKind::kPointOfLinePlane:
      return "Point";
    case TranslationKind::kEllipse:
      return "Ellipse";
    case TranslationKind::kShell:
      return "Shell";
    case TranslationKind::kThickCylinder:
      return "ThickCylinder";
    case TranslationKind::kSlab:
      return "Box";
    case TranslationKind::kPlanes:
      return "Planes";
    case TranslationKind::kBoundedCylinder:
      return "BoundedCylinder";
  }
  return "?";
}

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

namespace {
// The plane of a point-plane constraint in translation space (shapeOf's c and d without its
// in-plane direction, which costs a perpendicular and is not needed where this is used: the
// nearest-pose search evaluates these for every pose it tries).
void planeOf(const Fundamental& f, const Matrix3d& R, Vector3d* c, Vector3d* n) {
  const bool point_mobile = f.point_side == Side::kMobile;
  *c = point_mobile ? Vector3d(f.q - R * f.p) : Vector3d(f.p - R * f.q);
  *n = point_mobile ? f.d : Vector3d(R * f.d);
}
}  // namespace

int TranslationPart::dof() const {
  switch (kind) {
    case TranslationKind::kFree:
      return 3;
    case TranslationKind::kPoint:
      return 0;
    case TranslationKind::kLine:
      return 1;
    case TranslationKind::kPlane:
      return 2;
    case TranslationKind::kSphere:
      return 2;
    case TranslationKind::kCylinder:
      return 2;
    case TranslationKind::kLineOfPlanes:
      return 1;
    case TranslationKind::kPointOfLinePlane:
      return 0;
    case TranslationKind::kEllipse:
      return 1;
    case TranslationKind::kShell:
    case TranslationKind::kThickCylinder:
    case TranslationKind::kSlab:
      return 3;
    case TranslationKind::kPlanes:
      return 3 - planeRows() + rangedPlanes();
    case TranslationKind::kBoundedCylinder:
      return 1 + !c1.exact() + !c2.exact();
  }
  return 0;
}

Parameter TranslationPart::parameter(int i) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Parameter len{"lambda", ParamKind::kLength, -inf, inf, false};
  Parameter ang{"alpha", ParamKind::kAngle, -kPi, kPi, true};
  switch (kind) {
    case TranslationKind::kFree:
      len.name = i == 0 ? "x" : (i == 1 ? "y" : "z");
      return len;
    case TranslationKind::kLine:
    case TranslationKind::kLineOfPlanes:
      return len;
    case TranslationKind::kPlane:
      len.name = i == 0 ? "lambda1" : "lambda2";
      return len;
    case TranslationKind::kSphere:
      if (i == 1) return Parameter{"beta", ParamKind::kAngle, 0.0, kPi, false};
      return ang;
    case TranslationKind::kCylinder:
      return i == 0 ? len : ang;
    case TranslationKind::kEllipse:
      return ang;
    case TranslationKind::kShell:
      if (i == 2) return rangeParameter();
      if (i == 1) return Parameter{"beta", ParamKind::kAngle, 0.0, kPi, false};
      return ang;
    case TranslationKind::kThickCylinder:
      return i == 0 ? len : (i == 1 ? ang : rangeParameter());
    case TranslationKind::kSlab:
      if (i == 2) return rangeParameter();
      len.name = i == 0 ? "lambda1" : "lambda2";
      return len;
    case TranslationKind::kPlanes: {
      const int free = 3 - planeRows();
      if (i < free) {
        len.name = free == 1 ? "lambda" : (i == 0 ? "lambda1" : "lambda2");
        return len;
      }
      int r = i - free;
      for (const Fundamental& f : linear)
        if (!f.exact() && r-- == 0)
          return Parameter{"distance", ParamKind::kLength, f.lo, f.hi, false};
      return len;
    }
    case TranslationKind::kBoundedCylinder:
      if (i == 0) return ang;
      if (i == 1 && !c1.exact())
        return Parameter{"radius", ParamKind::kLength, c1.lo, c1.hi, false};
      return Parameter{"height", ParamKind::kLength, c2.lo, c2.hi, false};
    case TranslationKind::kPoint:
    case TranslationKind::kPointOfLinePlane:
      break;
  }
  return len;
}

namespace {

// kPlanes, for a given R: each linear constraint as rows n·T = h0 + sign·v (v = the range
// parameter for a ranged plane, 0 otherwise).
struct PlaneRows {
  int k = 0;
  Vector3d n[3];
  double h0[3] = {0, 0, 0};
  double sign[3] = {1, 1, 1};
  int ranged[3] = {-1, -1, -1};     // index of the row's range parameter among the ranged planes
  Vector3d e1 = Vector3d::UnitX();  // in-plane direction of the first plane (for k = 1)
};

PlaneRows planeRowsFor(const FixedVector<Fundamental, 3>& linear, const Matrix3d& R) {
  PlaneRows rows;
  int n_ranged = 0;
  auto add = [&](const Vector3d& n, double h0, double sign, int ranged) {
    if (rows.k == 3) return;
    rows.n[rows.k] = n;
    rows.h0[rows.k] = h0;
    rows.sign[rows.k] = sign;
    rows.ranged[rows.k] = ranged;
    ++rows.k;
  };
  for (const Fundamental& f : linear) {
    switch (f.kind) {
      case FundamentalKind::kPointPlane: {
        // The in-plane direction only for a lone plane (k = 1), the one case that needs it.
        Vector3d c, d;
        planeOf(f, R, &c, &d);
        if (linear.size() == 1) rows.e1 = shapeOf(f, R).e1;
        add(d, d.dot(c), f.point_side == Side::kMobile ? 1.0 : -1.0, f.exact() ? -1 : n_ranged++);
        break;
      }
      case FundamentalKind::kPointLine: {  // exact, on the line: two planes through it
        const TShape s = shapeOf(f, R);
        const Vector3d e2 = s.d.cross(s.e1);
        add(s.e1, s.e1.dot(s.c), 1.0, -1);
        add(e2, e2.dot(s.c), 1.0, -1);
        break;
      }
      case FundamentalKind::kPointPoint: {  // exact, pinned: three planes
        const TShape s = shapeOf(f, R);
        for (int a = 0; a < 3; ++a) add(Vector3d::Unit(a), s.c[a], 1.0, -1);
        break;
      }
      case FundamentalKind::kAngle:
      case FundamentalKind::kLineLine:
      case FundamentalKind::kCustom:
        break;
    }
  }
  return rows;
}

// The point of {x : n[i]·x = h[i], i < m} nearest the origin, x = Nᵀ (N Nᵀ)⁻¹ h, with fixed-size
// matrices so evaluating a pose never allocates (the rows are independent: the matcher checked).
Vector3d flatPoint(const Vector3d* n, const double* h, int m) {
  if (m == 0) return Vector3d::Zero();
  if (m == 1) return n[0] * (h[0] / n[0].squaredNorm());
  if (m == 2) {
    Eigen::Matrix2d G;
    G << n[0].dot(n[0]), n[0].dot(n[1]), n[1].dot(n[0]), n[1].dot(n[1]);
    const Eigen::Vector2d l = G.inverse() * Eigen::Vector2d(h[0], h[1]);
    return l[0] * n[0] + l[1] * n[1];
  }
  // Three rows: their one common point, by Cramer's rule in cross products.
  const Vector3d c12 = n[1].cross(n[2]), c20 = n[2].cross(n[0]), c01 = n[0].cross(n[1]);
  return (h[0] * c12 + h[1] * c20 + h[2] * c01) / n[0].dot(c12);
}

// T on every plane at the given range values, and the free directions.
Vector3d planesPoint(const PlaneRows& rows, const double* v, Vector3d free[2]) {
  double h[3];
  for (int i = 0; i < rows.k; ++i)
    h[i] = rows.h0[i] + (rows.ranged[i] >= 0 ? rows.sign[i] * v[rows.ranged[i]] : 0.0);
  if (rows.k == 2) free[0] = rows.n[0].cross(rows.n[1]).normalized();
  if (rows.k == 1) {
    free[0] = rows.e1;
    free[1] = rows.n[0].cross(rows.e1);
  }
  return flatPoint(rows.n, h, rows.k);
}

// The projection of T onto the flat where rows `active` (a bit mask) hold n·x = b.
Vector3d ontoFlat(const PlaneRows& rows, unsigned active, const double* b, const Vector3d& T) {
  Vector3d n[3];
  double r[3];
  int m = 0;
  for (int i = 0; i < rows.k; ++i)
    if (active & (1u << i)) n[m] = rows.n[i], r[m] = rows.n[i].dot(T) - b[i], ++m;
  return T - flatPoint(n, r, m);
}

// The point of the set (exact rows held, ranged rows within their bounds) nearest T: every way
// of holding each ranged row at a bound or leaving it free (at most 3³), each the projection of T
// onto its flat; the nearest that keeps the free rows within bounds is the answer, since the
// optimum's own active set is among them. (Clamping the heights one by one is exact only for
// orthogonal rows.)
Vector3d nearestOnRows(const PlaneRows& rows, const FixedVector<Fundamental, 3>& linear,
                       const Vector3d& T) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  unsigned ranged = 0, exact = 0;
  const Fundamental* by_range[3] = {nullptr, nullptr, nullptr};
  int r = 0;
  for (const Fundamental& f : linear)
    if (!f.exact()) by_range[r++] = &f;
  for (int i = 0; i < rows.k; ++i) {
    if (rows.ranged[i] < 0) {
      exact |= 1u << i;
      lo[i] = hi[i] = rows.h0[i];
      continue;
    }
    ranged |= 1u << i;
    const Fundamental& f = *by_range[rows.ranged[i]];
    const double a = rows.h0[i] + rows.sign[i] * f.lo, b = rows.h0[i] + rows.sign[i] * f.hi;
    lo[i] = std::min(a, b), hi[i] = std::max(a, b);
  }
  Vector3d best = T;
  double best_d = std::numeric_limits<double>::infinity();
  int combos = 1;
  for (int i = 0; i < rows.k; ++i)
    if (ranged & (1u << i)) combos *= 3;
  for (int c = 0; c < combos; ++c) {
    unsigned active = exact;
    double b[3] = {lo[0], lo[1], lo[2]};
    for (int i = 0, code = c; i < rows.k; ++i) {
      if (!(ranged & (1u << i))) continue;
      const int state = code % 3;  // 0: free, 1: at lo, 2: at hi
      code /= 3;
      if (state == 0) continue;
      active |= 1u << i;
      b[i] = state == 1 ? lo[i] : hi[i];
    }
    const Vector3d x = ontoFlat(rows, active, b, T);
    bool inside = true;
    for (int i = 0; i < rows.k && inside; ++i) {
      if (!(ranged & (1u << i)) || (active & (1u << i))) continue;
      const double h = rows.n[i].dot(x), slack = 1e-12 * (1.0 + std::abs(h));
      inside = h >= lo[i] - slack && h <= hi[i] + slack;
    }
    const double d = (x - T).squaredNorm();
    // No ranged row held and all within bounds: the projection onto the exact rows' flat, which
    // is nearer than any point of the set.
    if (inside && c == 0) return x;
    if (inside && d < best_d) best_d = d, best = x;
  }
  return best;
}

}  // namespace

int TranslationPart::planeRows() const { return planeRowsFor(linear, Matrix3d::Identity()).k; }

int TranslationPart::rangedPlanes() const {
  int n = 0;
  for (const Fundamental& f : linear) n += !f.exact();
  return n;
}

bool TranslationPart::projectsExactly() const {
  switch (kind) {
    case TranslationKind::kEllipse:
      return false;
    case TranslationKind::kPlanes:
      return true;  // nearestOnRows
    case TranslationKind::kBoundedCylinder: {
      // Square cuts only; line and plane are on the same object, so this holds for every R.
      const Matrix3d I = Matrix3d::Identity();
      return shapeOf(c1, I).d.cross(shapeOf(c2, I).d).norm() < 1e-12;
    }
    default:
      return true;
  }
}

namespace {

// Within rounding of an exact zero, relative to the vector's length: a feature off the axis by
// more than that moves with the spin, and the spin is then searched like any parameter.
bool alongAxis(const Vector3d& v, const Vector3d& u) {
  return v.cross(u).norm() <= 1e-12 * (1.0 + v.norm());
}

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

}  // namespace

bool TranslationPart::invariantUnderSpin(const Vector3d& u) const {
  switch (kind) {
    case TranslationKind::kFree:
      return true;
    case TranslationKind::kPlanes:
      for (const Fundamental& f : linear)
        if (!mobileGeometryInvariant(f, u)) return false;
      return true;
    case TranslationKind::kPoint:
    case TranslationKind::kLine:
    case TranslationKind::kPlane:
    case TranslationKind::kSphere:
    case TranslationKind::kCylinder:
    case TranslationKind::kShell:
    case TranslationKind::kThickCylinder:
    case TranslationKind::kSlab:
      return mobileGeometryInvariant(c1, u);
    case TranslationKind::kLineOfPlanes:
    case TranslationKind::kPointOfLinePlane:
    case TranslationKind::kEllipse:
    case TranslationKind::kBoundedCylinder:
      return mobileGeometryInvariant(c1, u) && mobileGeometryInvariant(c2, u);
  }
  return false;
}

void TranslationPart::translate(const Vector3d& offset_W, const Vector3d& offset_M) {
  c1.translate(offset_W, offset_M);
  c2.translate(offset_W, offset_M);
  for (Fundamental& f : linear) f.translate(offset_W, offset_M);
}

Parameter TranslationPart::rangeParameter() const {
  return Parameter{"distance", ParamKind::kLength, c1.lo, c1.hi, false};
}

namespace {

// Intersection line of two non-parallel planes (point closest to the first plane's point).
void planePlane(const TShape& a, const TShape& b, Vector3d* point, Vector3d* dir) {
  *point = pointWherePlanesMeet(a.c, a.d, b.c, b.d);
  *dir = accurateCross(a.d, b.d).normalized();
}

Vector3d linePlane(const Vector3d& c, const Vector3d& d, const TShape& plane) {
  return c + ((plane.c - c).dot(plane.d) / d.dot(plane.d)) * d;
}

// The two in-plane axes of the ellipse cut by a cylinder (axis d, radius r) from a plane
// (normal n): e1 ⊥ d and n, e2 = n × e1, semi-axes r and r / |d·n| (PMF eq. 10).
void ellipseAxes(const TShape& cyl, const TShape& plane, Vector3d* e1, Vector3d* e2, double* b) {
  Vector3d w = plane.d.cross(cyl.d);
  *e1 = w.norm() > 1e-12 ? Vector3d(w.normalized()) : cyl.e1;
  *e2 = plane.d.cross(*e1);
  *b = cyl.r / std::abs(cyl.d.dot(plane.d));
}

}  // namespace

Vector3d TranslationPart::translation(const Matrix3d& R, const double* t) const {
  if (kind == TranslationKind::kFree) return Vector3d(t[0], t[1], t[2]);
  if (kind == TranslationKind::kPlanes) {
    const PlaneRows rows = planeRowsFor(linear, R);
    const int free = 3 - rows.k;
    Vector3d dirs[2];
    Vector3d T = planesPoint(rows, t + free, dirs);
    for (int j = 0; j < free; ++j) T += t[j] * dirs[j];
    return T;
  }
  if (kind == TranslationKind::kBoundedCylinder) {
    const TShape cyl = shapeOf(c1, R);
    Vector3d pc, pn;
    planeOf(c2, R, &pc, &pn);
    const double r = c1.exact() ? c1.value() : t[1];
    const double v = c2.exact() ? 0.0 : t[c1.exact() ? 1 : 2];
    const double sign = c2.point_side == Side::kMobile ? 1.0 : -1.0;
    const double h = pn.dot(pc) + sign * v;  // the plane n·T = h
    // Out from the axis along the azimuth, then along the axis onto the plane (an oblique plane
    // cuts the thick cylinder obliquely: Somani's oblique cylinder).
    const Vector3d u = std::cos(t[0]) * cyl.e1 + std::sin(t[0]) * cyl.d.cross(cyl.e1);
    const double s = (h - pn.dot(cyl.c) - r * pn.dot(u)) / pn.dot(cyl.d);
    return cyl.c + s * cyl.d + r * u;
  }
  const TShape s = shapeOf(c1, R);
  const Vector3d e2 = s.d.cross(s.e1);
  switch (kind) {
    case TranslationKind::kPoint:
      return s.c;
    case TranslationKind::kLine:
      return s.c + t[0] * s.d;
    case TranslationKind::kPlane:
      return s.c + t[0] * s.e1 + t[1] * e2;
    case TranslationKind::kSphere:
      return s.c + s.r * Vector3d(std::cos(t[0]) * std::sin(t[1]), std::sin(t[0]) * std::sin(t[1]),
                                  std::cos(t[1]));
    case TranslationKind::kCylinder:
      return s.c + t[0] * s.d + s.r * (std::cos(t[1]) * s.e1 + std::sin(t[1]) * e2);
    case TranslationKind::kLineOfPlanes: {
      Vector3d p, d;
      planePlane(s, shapeOf(c2, R), &p, &d);
      return p + t[0] * d;
    }
    case TranslationKind::kPointOfLinePlane:
      return linePlane(s.c, s.d, shapeOf(c2, R));
    case TranslationKind::kEllipse: {
      const TShape pl = shapeOf(c2, R);
      Vector3d a1, a2;
      double b;
      ellipseAxes(s, pl, &a1, &a2, &b);
      return linePlane(s.c, s.d, pl) + s.r * std::cos(t[0]) * a1 + b * std::sin(t[0]) * a2;
    }
    case TranslationKind::kShell:
      return s.c + t[2] * Vector3d(std::cos(t[0]) * std::sin(t[1]), std::sin(t[0]) * std::sin(t[1]),
                                   std::cos(t[1]));
    case TranslationKind::kThickCylinder:
      return s.c + t[0] * s.d + t[2] * (std::cos(t[1]) * s.e1 + std::sin(t[1]) * e2);
    case TranslationKind::kSlab:
      return s.c + t[0] * s.e1 + t[1] * e2 + slabSign() * t[2] * s.d;
    case TranslationKind::kFree:
    case TranslationKind::kPlanes:  // handled above
    case TranslationKind::kBoundedCylinder:
      break;
  }
  return Vector3d::Zero();
}

// The nearest point of the set, then its range values (its heights over the planes) and its free
// coordinates; returns the translation at those parameters.
Vector3d TranslationPart::projectOntoPlanes(const Matrix3d& R, const Vector3d& T, double* t) const {
  const PlaneRows rows = planeRowsFor(linear, R);
  const Vector3d N = nearestOnRows(rows, linear, T);
  const int free = 3 - rows.k;
  double* v = t + free;
  int r = 0;
  for (const Fundamental& f : linear) {
    if (f.exact()) continue;
    for (int i = 0; i < rows.k; ++i)
      if (rows.ranged[i] == r) {
        const double x = rows.sign[i] * (rows.n[i].dot(N) - rows.h0[i]);
        v[r] = std::min(f.hi, std::max(f.lo, x));
      }
    ++r;
  }
  Vector3d dirs[2];
  Vector3d P = planesPoint(rows, v, dirs);
  const Vector3d foot = P;
  for (int j = 0; j < free; ++j) {
    t[j] = dirs[j].dot(T - foot);
    P += t[j] * dirs[j];
  }
  return P;
}

Vector3d TranslationPart::projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const {
  if (kind == TranslationKind::kPlanes) return projectOntoPlanes(R, T, t);
  project(R, T, t);
  return translation(R, t);
}

void TranslationPart::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  if (kind == TranslationKind::kFree) {
    t[0] = T.x(), t[1] = T.y(), t[2] = T.z();
    return;
  }
  if (kind == TranslationKind::kPlanes) {
    projectOntoPlanes(R, T, t);
    return;
  }
  if (kind == TranslationKind::kBoundedCylinder) {
    const TShape cyl = shapeOf(c1, R);
    Vector3d pc, pn;
    planeOf(c2, R, &pc, &pn);
    const Vector3d w = T - cyl.c;
    const double along = w.dot(cyl.d);
    const Vector3d perp = w - along * cyl.d;
    const Vector3d e2 = cyl.d.cross(cyl.e1);
    t[0] = std::atan2(perp.dot(e2), perp.dot(cyl.e1));
    int k = 1;
    if (!c1.exact()) t[k++] = std::min(c1.hi, std::max(c1.lo, perp.norm()));
    if (!c2.exact()) {
      const double sign = c2.point_side == Side::kMobile ? 1.0 : -1.0;
      t[k] = std::min(c2.hi, std::max(c2.lo, sign * (pn.dot(T) - pn.dot(pc))));
    }
    return;
  }
  const TShape s = shapeOf(c1, R);
  const Vector3d e2 = s.d.cross(s.e1);
  const Vector3d v = T - s.c;
  switch (kind) {
    case TranslationKind::kLine:
      t[0] = v.dot(s.d);
      return;
    case TranslationKind::kPlane:
      t[0] = v.dot(s.e1), t[1] = v.dot(e2);
      return;
    case TranslationKind::kSphere:
      if (v.norm() < 1e-300) {
        t[0] = t[1] = 0.0;
      } else {
        t[0] = std::atan2(v.y(), v.x());
        t[1] = std::acos(clampUnit(v.z() / v.norm()));
      }
      return;
    case TranslationKind::kCylinder:
      t[0] = v.dot(s.d);
      t[1] = std::atan2(v.dot(e2), v.dot(s.e1));
      return;
    case TranslationKind::kLineOfPlanes: {
      Vector3d p, d;
      planePlane(s, shapeOf(c2, R), &p, &d);
      t[0] = (T - p).dot(d);
      return;
    }
    case TranslationKind::kEllipse: {
      const TShape pl = shapeOf(c2, R);
      Vector3d a1, a2;
      double b;
      ellipseAxes(s, pl, &a1, &a2, &b);
      Vector3d w = T - linePlane(s.c, s.d, pl);
      t[0] = std::atan2(w.dot(a2) / b, w.dot(a1) / s.r);
      return;
    }
    case TranslationKind::kShell: {
      const double r = v.norm();
      t[0] = r > 1e-300 ? std::atan2(v.y(), v.x()) : 0.0;
      t[1] = r > 1e-300 ? std::acos(clampUnit(v.z() / r)) : 0.0;
      t[2] = clampRange(r);
      return;
    }
    case TranslationKind::kThickCylinder: {
      t[0] = v.dot(s.d);
      const Vector3d perp = v - t[0] * s.d;
      t[1] = std::atan2(perp.dot(e2), perp.dot(s.e1));
      t[2] = clampRange(perp.norm());
      return;
    }
    case TranslationKind::kSlab:
      t[0] = v.dot(s.e1);
      t[1] = v.dot(e2);
      t[2] = clampRange(slabSign() * v.dot(s.d));
      return;
    case TranslationKind::kPoint:
    case TranslationKind::kPointOfLinePlane:
    case TranslationKind::kFree:
    case TranslationKind::kPlanes:  // handled above
    case TranslationKind::kBoundedCylinder:
      return;
  }
}

}  // namespace relpos::manifolds
