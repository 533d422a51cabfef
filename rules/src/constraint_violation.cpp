// How far a pose is from meeting each built-in constraint type (docs/spec.md §1, "holds when"), in
// units of the tolerance: the solver's last check of every branch it returns (solver.cpp). Written
// from the spec's table, not from the decomposition, so that it catches what a rule got wrong.
// (The tests keep their own evaluator, tests/support/evaluator.cpp, so that each checks the other.)
#include "constraint_violation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relpos::rules {
namespace {

using K = FeatureKind;

// Angles through atan2, so that near 0, π and ±π/2 rounding stays rounding.
double angleOf(const Vector3d& u, const Vector3d& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

double parallelAngle(const Vector3d& m, const Vector3d& f, Orientation o) {
  switch (o) {
    case Orientation::kAligned:
      return angleOf(m, f);
    case Orientation::kOpposed:
      return angleOf(m, -f);
    case Orientation::kEither:
      break;
  }
  return std::min(angleOf(m, f), angleOf(m, -f));
}

double pointLine(const Vector3d& p, const Feature& l) {
  return (p - l.point).cross(l.direction).norm();
}
double pointPlane(const Vector3d& p, const Feature& pl) { return (p - pl.point).dot(pl.direction); }

// Parallel within the angle tolerance, the common perpendicular's direction is rounding: the
// lines' distance is then read at b's point.
double skewDistance(const Feature& a, const Feature& b, const Tolerance& tol) {
  const Vector3d n = accurateCross(a.direction, b.direction);
  const double s = n.norm();
  if (!(s > tol.angle)) return pointLine(b.point, a);
  return std::abs((b.point - a.point).dot(n)) / s;
}

// Outside the value or the [min, max] range.
double off(double x, const InputConstraint& c) {
  if (c.has_value) return std::abs(x - c.value);
  return std::max({c.min - x, x - c.max, 0.0});
}

// The worse of a length and an angle violation, each in its tolerance.
struct Worst {
  const Tolerance& tol;
  double v = 0.0;
  void length(double x) { v = std::max(v, std::isnan(x) ? kInf : std::abs(x) / tol.length); }
  void angle(double x) { v = std::max(v, std::isnan(x) ? kInf : std::abs(x) / tol.angle); }
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

const Feature& pointOf(const Feature& F, const Feature& M) { return M.kind == K::kPoint ? M : F; }
const Feature& otherOf(const Feature& F, const Feature& M) { return M.kind == K::kPoint ? F : M; }
const Feature& ofKind(K k, const Feature& F, const Feature& M) { return F.kind == k ? F : M; }
bool isPair(K a, K b, const Feature& F, const Feature& M) {
  return (F.kind == a && M.kind == b) || (F.kind == b && M.kind == a);
}

// distance and coincident (coincident: the distance 0, a point on a cylinder at its radius).
void distanceLike(const InputConstraint& c, const Feature& F, const Feature& M, bool coincident,
                  Worst& w) {
  auto value = [&](double x) { return coincident ? x : off(x, c); };
  if (F.kind == K::kPoint || M.kind == K::kPoint) {
    const Feature& P = pointOf(F, M);
    const Feature& X = otherOf(F, M);
    switch (X.kind) {
      case K::kPoint:
        return w.length(value((P.point - X.point).norm()));
      case K::kLine:
        return w.length(value(pointLine(P.point, X)));
      case K::kPlane:
        return w.length(value(pointPlane(P.point, X)));
      case K::kCylinder:
        return w.length(pointLine(P.point, X) - X.radius);
    }
  }
  if (F.kind == K::kLine && M.kind == K::kLine) {
    if (!coincident && !c.parallel) return w.length(off(skewDistance(F, M, w.tol), c));
    w.angle(parallelAngle(M.direction, F.direction, c.orientation));
    return w.length(value(pointLine(M.point, F)));
  }
  if (isPair(K::kLine, K::kPlane, F, M)) {
    const Feature& L = ofKind(K::kLine, F, M);
    const Feature& Pl = ofKind(K::kPlane, F, M);
    w.angle(std::asin(std::min(1.0, std::abs(L.direction.dot(Pl.direction)))));
    return w.length(value(pointPlane(L.point, Pl)));
  }
  // plane-plane: along the fixed plane's normal.
  w.angle(parallelAngle(M.direction, F.direction, c.orientation));
  w.length(value((M.point - F.point).dot(F.direction)));
}

void angle(const InputConstraint& c, const Feature& F, const Feature& M, Worst& w) {
  if (F.kind != M.kind) {
    const Feature& L = ofKind(K::kLine, F, M);
    const Feature& Pl = ofKind(K::kPlane, F, M);
    return w.angle(off(kPi / 2 - angleOf(L.direction, Pl.direction), c));
  }
  w.angle(off(angleOf(F.direction, M.direction), c));
}

void tangent(const InputConstraint& c, const Feature& F, const Feature& M, Worst& w) {
  if (F.kind == K::kCylinder && M.kind == K::kCylinder) {
    w.angle(parallelAngle(M.direction, F.direction, Orientation::kEither));
    return w.length(pointLine(M.point, F) - (F.radius + M.radius));
  }
  if (isPair(K::kCylinder, K::kPlane, F, M)) {
    const Feature& C = ofKind(K::kCylinder, F, M);
    const Feature& Pl = ofKind(K::kPlane, F, M);
    const double s = pointPlane(C.point, Pl);
    double side = std::numeric_limits<double>::infinity();
    if (c.orientation != Orientation::kOpposed) side = std::min(side, std::abs(s + C.radius));
    if (c.orientation != Orientation::kAligned) side = std::min(side, std::abs(s - C.radius));
    w.angle(std::asin(std::min(1.0, std::abs(C.direction.dot(Pl.direction)))));
    return w.length(side);
  }
  const Feature& C = ofKind(K::kCylinder, F, M);
  const Feature& L = &C == &F ? M : F;
  w.length(skewDistance(C, L, w.tol) - C.radius);
}

}  // namespace

double distanceViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                         const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  distanceLike(c, F, M, false, w);
  return w.v;
}

double coincidentViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                           const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  distanceLike(c, F, M, true, w);
  return w.v;
}

double angleViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                      const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  angle(c, F, M, w);
  return w.v;
}

// Line-line and plane-plane per orientation; a line parallel to a plane: d·n = 0.
double parallelViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                         const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  w.angle(F.kind != M.kind ? std::asin(std::min(1.0, std::abs(F.direction.dot(M.direction))))
                           : parallelAngle(M.direction, F.direction, c.orientation));
  return w.v;
}

// Line-line and plane-plane: d·d = 0; a line perpendicular to a plane: along its normal.
double perpendicularViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                              const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  w.angle(F.kind != M.kind ? parallelAngle(M.direction, F.direction, c.orientation)
                           : std::asin(std::min(1.0, std::abs(F.direction.dot(M.direction)))));
  return w.v;
}

double tangentViolation(const InputConstraint& c, const Feature& F, const Feature& M,
                        const Tolerance& tol, const void* /*context*/) {
  Worst w{tol};
  tangent(c, F, M, w);
  return w.v;
}

}  // namespace relpos::rules
