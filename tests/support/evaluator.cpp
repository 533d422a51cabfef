#include "evaluator.hpp"

#include <algorithm>
#include <cmath>

#include "world_feature.hpp"

namespace relpos::test {
namespace {

using K = FeatureKind;

using W = WorldFeature;

double elevation(const Vector3d& d, const Vector3d& n) {
  return 3.14159265358979323846 / 2 - angleOf(d, n);
}

// Directions parallel per orientation: 0 when they hold.
double parallelViolation(const Vector3d& u, const Vector3d& v, Orientation o) {
  switch (o) {
    case Orientation::kAligned:
      return angleOf(u, v);
    case Orientation::kOpposed:
      return angleOf(u, -v);
    case Orientation::kEither:
      return std::min(angleOf(u, v), angleOf(u, -v));
  }
  return 1e9;
}

double pointLine(const Vector3d& p, const W& l) { return (p - l.a).cross(l.d).norm(); }
double pointPlane(const Vector3d& p, const W& pl) { return (p - pl.a).dot(pl.d); }

// Lines within the angle tolerance (1e-9 rad) of parallel are parallel (docs/spec.md §1.9): their
// distance is l2's point's from l1. Below it the common perpendicular's direction is rounding, and
// a pose 1.25e-12 rad from parallel read 8.8e-6 off at coordinates 1e6 (seed offset 7005).
double skewDistance(const W& l1, const W& l2) {
  Vector3d n = l1.d.cross(l2.d);
  if (n.norm() <= 1e-9) return pointLine(l2.a, l1);
  return std::abs((l2.a - l1.a).dot(n)) / n.norm();
}

// |x - target| for exact constraints, distance outside [min, max] for ranges.
double off(double x, const InputConstraint& c) {
  if (c.has_value) return std::abs(x - c.value);
  if (x < c.min) return c.min - x;
  if (x > c.max) return x - c.max;
  return 0.0;
}

// The mobile line runs along the fixed axis, same direction; with R0 the shortest rotation
// taking the mobile direction (mobile frame) onto the axis, R = Rot(d, θ) R0 and the line's point
// sits at q + (pitch θ / 2π) d for some real θ: the advance is pitch·φ/2π up to whole pitches.
double threadViolation(const InputConstraint& c, const W& F, const W& M, const Isometry3d& X_WM) {
  const Matrix3d R0 = Quaterniond::FromTwoVectors(c.mobile.direction, F.d).toRotationMatrix();
  const Eigen::AngleAxisd turn(X_WM.linear() * R0.transpose());
  const double phi = turn.angle() * (turn.axis().dot(F.d) >= 0 ? 1.0 : -1.0);
  const double advance = (M.a - F.a).dot(F.d) - c.value * phi / (2 * 3.14159265358979323846);
  const double phase = std::abs(advance - c.value * std::round(advance / c.value));
  return std::max({angleOf(M.d, F.d), pointLine(M.a, F), phase});
}

}  // namespace

double violation(const InputConstraint& c, const Isometry3d& X_WF, const Isometry3d& X_WM) {
  const W F = placeInWorld(c.fixed, X_WF), M = placeInWorld(c.mobile, X_WM);
  const std::string& t = c.type;
  const bool has_point = F.kind == K::kPoint || M.kind == K::kPoint;
  const W& P = M.kind == K::kPoint ? M : F;  // the point, when there is one
  const W& X = M.kind == K::kPoint ? F : M;  // the other feature
  auto both = [&](K a, K b) {
    return (F.kind == a && M.kind == b) || (F.kind == b && M.kind == a);
  };
  if (t == "distance" || t == "coincident") {
    const bool dist = t == "distance";
    const InputConstraint& cc = c;
    auto val = [&](double x) { return dist ? off(x, cc) : std::abs(x); };
    if (has_point) {
      switch (X.kind) {
        case K::kPoint:
          return val((P.a - X.a).norm());
        case K::kLine:
          return val(pointLine(P.a, X));
        case K::kPlane:
          return val(pointPlane(P.a, X));
        case K::kCylinder:
          return std::abs(pointLine(P.a, X) - X.r);  // point on cylinder
      }
    }
    if (F.kind == K::kLine && M.kind == K::kLine) {
      if (dist && !c.parallel) return off(skewDistance(F, M), c);
      return std::max(parallelViolation(M.d, F.d, c.orientation), val(pointLine(M.a, F)));
    }
    if (both(K::kLine, K::kPlane)) {
      const W& L = F.kind == K::kLine ? F : M;
      const W& Pl = F.kind == K::kPlane ? F : M;
      return std::max(std::abs(L.d.dot(Pl.d)), val(pointPlane(L.a, Pl)));
    }
    if (F.kind == K::kPlane && M.kind == K::kPlane)
      return std::max(parallelViolation(M.d, F.d, c.orientation), val((M.a - F.a).dot(F.d)));
  }
  if (t == "angle") {
    if (both(K::kLine, K::kPlane)) {
      const W& L = F.kind == K::kLine ? F : M;
      const W& Pl = F.kind == K::kPlane ? F : M;
      return off(elevation(L.d, Pl.d), c);
    }
    return off(angleOf(F.d, M.d), c);
  }
  if (t == "parallel") {
    if (F.kind != M.kind) return std::abs(F.d.dot(M.d));
    return parallelViolation(M.d, F.d, c.orientation);
  }
  if (t == "perpendicular") {
    if (F.kind != M.kind) return parallelViolation(M.d, F.d, c.orientation);
    return std::abs(F.d.dot(M.d));
  }
  if (t == "tangent") {
    if (F.kind == K::kCylinder && M.kind == K::kCylinder)
      return std::max(parallelViolation(M.d, F.d, Orientation::kEither),
                      std::abs(pointLine(M.a, F) - (F.r + M.r)));
    if (both(K::kCylinder, K::kPlane)) {
      const W& C = F.kind == K::kCylinder ? F : M;
      const W& Pl = F.kind == K::kPlane ? F : M;
      const double s = pointPlane(C.a, Pl);
      double side = 1e9;
      if (c.orientation != Orientation::kOpposed) side = std::min(side, std::abs(s + C.r));
      if (c.orientation != Orientation::kAligned) side = std::min(side, std::abs(s - C.r));
      return std::max(std::abs(C.d.dot(Pl.d)), side);
    }
    if (both(K::kCylinder, K::kLine)) {
      const W& C = F.kind == K::kCylinder ? F : M;
      const W& L = F.kind == K::kLine ? F : M;
      return std::abs(skewDistance(C, L) - C.r);
    }
  }
  // The example plugins' types, from their documentation (docs/spec.md §4.5).
  if (t == "symmetric")
    return std::max(parallelViolation(M.d, F.d, Orientation::kEither),
                    std::abs(pointPlane(M.a, F)));
  if (t == "thread") return threadViolation(c, F, M, X_WM);
  return 1e9;  // unknown to this evaluator: never "satisfied"
}

bool signedResidual(const InputConstraint& c, const Isometry3d& X_WF, const Isometry3d& X_WM,
                    double* residual) {
  if (!c.has_value) return false;
  const W F = placeInWorld(c.fixed, X_WF), M = placeInWorld(c.mobile, X_WM);
  const W& P = M.kind == K::kPoint ? M : F;
  const W& X = M.kind == K::kPoint ? F : M;
  const bool has_point = F.kind == K::kPoint || M.kind == K::kPoint;
  if (c.type == "distance" && has_point) {
    if (X.kind == K::kPoint)
      *residual = (P.a - X.a).norm() - c.value;
    else if (X.kind == K::kLine)
      *residual = pointLine(P.a, X) - c.value;
    else if (X.kind == K::kPlane)
      *residual = pointPlane(P.a, X) - c.value;
    else
      return false;
    return true;
  }
  if (c.type == "angle" && !has_point && F.kind != K::kCylinder && M.kind != K::kCylinder) {
    if (F.kind != M.kind) {
      const W& L = F.kind == K::kLine ? F : M;
      const W& Pl = F.kind == K::kPlane ? F : M;
      *residual = elevation(L.d, Pl.d) - c.value;
    } else {
      *residual = angleOf(F.d, M.d) - c.value;
    }
    return true;
  }
  return false;
}

double worstViolation(const Problem& p, const Isometry3d& X_WM, int* which) {
  double worst = 0.0;
  for (std::size_t i = 0; i < p.constraints.size(); ++i) {
    double v = violation(p.constraints[i], p.fixed.pose, X_WM);
    if (v > worst || std::isnan(v)) {
      worst = std::isnan(v) ? 1e9 : v;
      if (which) *which = static_cast<int>(i);
    }
  }
  return worst;
}

}  // namespace relpos::test
