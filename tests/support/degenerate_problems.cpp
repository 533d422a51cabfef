#include "degenerate_problems.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "world_feature.hpp"

namespace relpos::test {

WorldBuilder::WorldBuilder(Rng& rng) : rng_(rng), kp_(emptyKnownProblem(rng)) {
  kp_.problem.name = "degenerate";
}

// Upper-case names: addConstraint (random_problems.cpp) names its features f0, m0, ...
std::string WorldBuilder::fixed(const Feature& world) {
  const std::string name = "F" + std::to_string(features_++);
  kp_.problem.fixed.features.push_back({name, world.placed(kp_.problem.fixed.pose.inverse())});
  return name;
}

std::string WorldBuilder::mobile(const Feature& world) {
  const std::string name = "M" + std::to_string(features_++);
  kp_.problem.mobile.features.push_back({name, world.placed(kp_.X_WM_star.inverse())});
  return name;
}

void WorldBuilder::constrain(const std::string& type, const std::string& fixed_name,
                             const std::string& mobile_name, Value v, Orientation o,
                             bool parallel) {
  InputConstraint c;
  c.type = type;
  c.fixed = *kp_.problem.fixed.find(fixed_name);
  c.mobile = *kp_.problem.mobile.find(mobile_name);
  c.fixed_name = fixed_name;
  c.mobile_name = mobile_name;
  c.has_value = v.exact;
  c.value = v.value;
  c.min = v.exact ? v.value : v.min;
  c.max = v.exact ? v.value : v.max;
  c.orientation = o;
  c.parallel = parallel;
  kp_.problem.constraints.push_back(c);
}

void WorldBuilder::addGeneric() {
  const auto& kinds = singleKinds();
  addConstraint(kp_, kinds[rng_.integer(0, static_cast<int>(kinds.size()) - 1)], rng_);
}

namespace {

using F = Feature;
using WB = WorldBuilder;
constexpr double kEps = 2.220446049250313e-16;

const std::vector<double> kAngles = {1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};
const std::vector<double> kGaps = {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-12};
// A contact missed (> 0) or overshot (< 0) by this fraction of the radius: within rounding, well
// within the length tolerance, and just within it (radii are at most 1.5, the tolerance 1e-9 of
// the problem's size, which is at least the radius).
const std::vector<double> kTouch = {-5e-10, -1e-11, -1e-14, 0.0, 1e-14, 1e-11, 5e-10};

// u turned by `a` about a random axis perpendicular to it.
Vector3d tilt(const Vector3d& u, double a, Rng& r) {
  return Eigen::AngleAxisd(a, r.perpendicular(u)) * u;
}
// A random vector perpendicular to unit n, of length up to `half`.
Vector3d inPlane(const Vector3d& n, Rng& r, double half = 1.0) {
  const Vector3d v = r.point(half);
  return v - v.dot(n) * n;
}

double byAngle(double a) { return std::max(1e-6, 64 * kEps / a); }
double fixedTolerance(double) { return 1e-6; }
double byTouch(double eta) { return std::max(1e-6, 2 * std::sqrt(2 * std::abs(eta))); }
double rounding(double) { return 1e-12; }
double touchSlack(double eta) { return std::max(1e-12, 2 * std::abs(eta)); }

DegenerateFamily family(const std::string& name, const std::string& level_name,
                        std::vector<double> levels, std::function<double(double)> tol,
                        std::function<void(WB&, double, int)> build, int per_level = 16,
                        std::function<double(double)> slack = rounding) {
  DegenerateFamily f;
  f.name = name;
  f.level_name = level_name;
  f.levels = std::move(levels);
  f.per_level = per_level;
  f.known_tolerance = std::move(tol);
  f.known_slack = std::move(slack);
  f.build = std::move(build);
  return f;
}

// --- lines and planes a small angle from parallel -----------------------------------------------

void pointOnTwoLines(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit(), d2 = tilt(d, a, r);
  const std::string m = w.mobile(F::makePoint(A));
  w.constrain("coincident", w.fixed(F::makeLine(A + r.uniform(-1.5, 1.5) * d, d)), m);
  w.constrain("coincident", w.fixed(F::makeLine(A + r.uniform(-1.5, 1.5) * d2, d2)), m);
  if (k % 2) w.addGeneric();
}

void pointOnTwoPlanes(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), n = r.unit(), n2 = tilt(n, a, r);
  const std::string m = w.mobile(F::makePoint(A));
  for (const Vector3d& nn : {n, n2}) {
    if (k % 4 < 2) {
      w.constrain("coincident", w.fixed(F::makePlane(A + inPlane(nn, r), nn)), m);
    } else {  // signed distances from the two planes
      const double v = r.uniform(-1.5, 1.5);
      w.constrain("distance", w.fixed(F::makePlane(A - v * nn + inPlane(nn, r), nn)), m,
                  WB::exactly(v));
    }
  }
  if (k % 2) w.addGeneric();
}

void lineInTwoPlanes(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit(), n = r.perpendicular(d);
  const Vector3d n2 = Eigen::AngleAxisd(a, d) * n;  // both planes contain the line's direction
  const std::string m = w.mobile(F::makeLine(A + r.uniform(-1, 1) * d, d));
  for (const Vector3d& nn : {n, n2}) {
    if (k % 4 < 2) {
      w.constrain("coincident", w.fixed(F::makePlane(A + inPlane(nn, r), nn)), m);
    } else {
      const double v = r.uniform(-1.5, 1.5);
      w.constrain("distance", w.fixed(F::makePlane(A - v * nn + inPlane(nn, r), nn)), m,
                  WB::exactly(v));
    }
  }
  if (k % 2) w.addGeneric();
}

void twoPlaneContacts(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), n = r.unit(), n2 = tilt(n, a, r);
  for (const Vector3d& nn : {n, n2}) {
    const std::string m = w.mobile(F::makePlane(A + inPlane(nn, r), nn));
    if (k % 4 < 2) {  // face to face
      w.constrain("coincident", w.fixed(F::makePlane(A + inPlane(nn, r), -nn)), m, WB::Value(),
                  Orientation::kOpposed);
    } else {  // at a signed distance along the fixed normal
      const double v = r.uniform(-1.5, 1.5);
      w.constrain("distance", w.fixed(F::makePlane(A - v * nn + inPlane(nn, r), nn)), m,
                  WB::exactly(v));
    }
  }
  if (k % 2) w.addGeneric();
}

void twoLineCoincidences(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit(), d2 = tilt(d, a, r);
  for (int i = 0; i < 2; ++i) {
    const Vector3d& dd = i ? d2 : d;
    const std::string m = w.mobile(F::makeLine(A + r.uniform(-1, 1) * dd, dd));
    const bool either = i == 1 && k % 4 >= 2;  // the second one given reversed, either way
    w.constrain("coincident", w.fixed(F::makeLine(A + r.uniform(-1, 1) * dd, either ? -dd : dd)), m,
                WB::Value(), either ? Orientation::kEither : Orientation::kAligned);
  }
  if (k % 2) w.addGeneric();
}

// Rotation only: two directions a small angle apart kept parallel to two fixed ones.
void twoParallels(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d d = r.unit(), d2 = tilt(d, a, r);
  for (const Vector3d& dd : {d, d2}) {
    if (k % 4 < 2) {
      w.constrain("parallel", w.fixed(F::makeLine(r.point(), dd)),
                  w.mobile(F::makeLine(r.point(), dd)));
    } else {
      w.constrain("parallel", w.fixed(F::makePlane(r.point(), -dd)),
                  w.mobile(F::makePlane(r.point(), dd)), WB::Value(), Orientation::kOpposed);
    }
  }
  if (k % 2) w.addGeneric();
}

// --- points close together ---------------------------------------------------------------------

void twoPointsApart(WB& w, double gap, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), B = A + gap * r.unit();
  for (const Vector3d& P : {A, B})
    w.constrain("coincident", w.fixed(F::makePoint(P)), w.mobile(F::makePoint(P)));
  if (k % 3 == 1) {
    const Vector3d C = A + 1.5 * r.unit();
    w.constrain("coincident", w.fixed(F::makePoint(C)), w.mobile(F::makePoint(C)));
  }
  if (k % 3 == 2) w.addGeneric();
}

void threePointsNearlyCollinear(WB& w, double gap, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), u = r.unit(), B = A + r.uniform(1, 2) * u;
  const Vector3d C = A + r.uniform(0.2, 0.8) * (B - A) + gap * r.perpendicular(u);
  for (const Vector3d& P : {A, B, C})
    w.constrain("coincident", w.fixed(F::makePoint(P)), w.mobile(F::makePoint(P)));
  if (k % 2) w.addGeneric();
}

void nearlyConcentricSpheres(WB& w, double gap, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point();
  const Vector3d Q1 = A - r.uniform(0.3, 1.5) * r.unit(), Q2 = Q1 + gap * r.unit();
  const std::string m = w.mobile(F::makePoint(A));
  for (const Vector3d& Q : {Q1, Q2})
    w.constrain("distance", w.fixed(F::makePoint(Q)), m, WB::exactly((A - Q).norm()));
  if (k % 2) w.addGeneric();
}

// --- spheres that just touch ---------------------------------------------------------------------

void sphereTouchingPlane(WB& w, double eta, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), n = r.unit();
  const double radius = r.uniform(0.2, 1.5), side = k % 2 ? 1.0 : -1.0;
  const std::string m = w.mobile(F::makePoint(A));
  if (k % 4 < 2) {
    w.constrain("coincident", w.fixed(F::makePlane(A + inPlane(n, r), n)), m);
  } else {
    const double v = r.uniform(-1, 1);
    w.constrain("distance", w.fixed(F::makePlane(A - v * n + inPlane(n, r), n)), m, WB::exactly(v));
  }
  const Vector3d Q = A + side * radius * (1 + eta) * n;
  w.constrain("distance", w.fixed(F::makePoint(Q)), m, WB::exactly(radius));
}

void sphereTouchingLine(WB& w, double eta, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit();
  const double radius = r.uniform(0.2, 1.5);
  const std::string m = w.mobile(F::makePoint(A));
  w.constrain("coincident", w.fixed(F::makeLine(A + r.uniform(-1, 1) * d, d)), m);
  const Vector3d Q = A + radius * (1 + eta) * r.perpendicular(d);
  w.constrain("distance", w.fixed(F::makePoint(Q)), m, WB::exactly(radius));
  if (k % 2) w.addGeneric();
}

void spheresTouchingOutside(WB& w, double eta, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), u = r.unit();
  const double r1 = r.uniform(0.2, 1.5), r2 = r.uniform(0.2, 1.5);
  const std::string m = w.mobile(F::makePoint(A));
  w.constrain("distance", w.fixed(F::makePoint(A - r1 * u)), m, WB::exactly(r1));
  w.constrain("distance", w.fixed(F::makePoint(A + r2 * (1 + eta) * u)), m, WB::exactly(r2));
  if (k % 2) w.addGeneric();
}

void spheresTouchingInside(WB& w, double eta, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), u = r.unit();
  const double r1 = r.uniform(0.8, 1.5), r2 = r.uniform(0.1, 0.7);
  const std::string m = w.mobile(F::makePoint(A));
  w.constrain("distance", w.fixed(F::makePoint(A - r1 * u)), m, WB::exactly(r1));
  // The small sphere inside the big one, touching it at A (η > 0: pulled in, just short of it).
  w.constrain("distance", w.fixed(F::makePoint(A - r2 * (1 + eta) * u)), m, WB::exactly(r2));
  if (k % 2) w.addGeneric();
}

void sphereTouchingCylinder(WB& w, double eta, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit(), out = r.perpendicular(d);
  const double R = r.uniform(0.2, 1.5), radius = r.uniform(0.2, 1.5);
  const std::string m = w.mobile(F::makePoint(A));
  w.constrain("coincident", w.fixed(F::makeCylinder(A - R * out + r.uniform(-1, 1) * d, d, R)), m);
  w.constrain("distance", w.fixed(F::makePoint(A + radius * (1 + eta) * out)), m,
              WB::exactly(radius));
  if (k % 2) w.addGeneric();
}

// A point on a plane and another on a sphere that touches the plane, the two points a gap g
// apart along the normal, and (odd k) the sphere lifted 0.9e-9 off the plane: within the length
// tolerance. g is a fraction `f` of the solver's present length tolerance (1e-9 of
// Problem::lengthScale()), so that a rule taking the two points for one (their gap within the
// tolerance) and then testing the tangency separately sees a sphere that misses the plane by
// g + lift, beyond the tolerance: the square root of a small negative unless it guards it.
void sphereWithinToleranceOfPlane(WB& w, double f, int k) {
  Rng& r = w.rng();
  const double lift = k % 2 ? 0.9e-9 : 0.0;  // ≤ 0.9e-9 of the size: the size is at least 1
  auto make = [&](WB& b, double g) {
    Rng& rr = b.rng();
    const Vector3d A = rr.point(), n = rr.unit();
    const double radius = rr.uniform(1.0, 1.5);
    b.constrain("coincident", b.fixed(F::makePlane(A + inPlane(n, rr), n)),
                b.mobile(F::makePoint(A)));
    b.constrain("distance", b.fixed(F::makePoint(A + (g + radius + lift) * n)),
                b.mobile(F::makePoint(A + g * n)), WB::exactly(radius));
  };
  // First on a scratch copy with g = 0 for the problem's length scale, then for real from the
  // same random state.
  const Rng saved = r;
  WB scratch = w;
  make(scratch, 0.0);
  const double tol = 1e-9 * std::max(1.0, scratch.known().problem.lengthScale());
  r = saved;
  make(w, f * tol);
}

// --- cones and angles ----------------------------------------------------------------------------

void twoConesApart(WB& w, double gap, int k) {
  Rng& r = w.rng();
  const Vector3d u = r.unit(), d1 = tilt(u, r.uniform(0.3, 2.8), r), d2 = tilt(d1, gap, r);
  const bool planes = k % 2;
  const std::string m = w.mobile(planes ? F::makePlane(r.point(), u) : F::makeLine(r.point(), u));
  for (const Vector3d& d : {d1, d2})
    w.constrain("angle", w.fixed(planes ? F::makePlane(r.point(), d) : F::makeLine(r.point(), d)),
                m, WB::exactly(angleOf(u, d)));
  if (k % 4 >= 2) w.addGeneric();
}

// Angles at or within ε of a special value: which pair of kinds and which value.
struct SpecialAngle {
  FeatureKind fixed, mobile;
  double target;
  double lo, hi;  // the domain of the value (docs/spec.md §1)
};

// The fixed direction for a mobile direction u and angle value v.
Vector3d fixedDirectionFor(const SpecialAngle& s, const Vector3d& u, double v, Rng& r) {
  const bool line_plane = s.fixed != s.mobile;
  // line–plane: arcsin(d·n) = v, so d and n are π/2 − v apart.
  return tilt(u, line_plane ? kPi / 2 - v : v, r);
}

void specialAngle(const SpecialAngle& s, WB& w, double eps, int k) {
  Rng& r = w.rng();
  // Towards the inside of the domain at its ends; from either side in its interior.
  const double sign = s.target == s.lo ? 1.0 : s.target == s.hi ? -1.0 : (k % 2 ? 1.0 : -1.0);
  const double v = s.target + sign * eps, width = 1e-9;
  auto feature = [&](FeatureKind kind, const Vector3d& dir) {
    return kind == FeatureKind::kLine ? F::makeLine(r.point(), dir) : F::makePlane(r.point(), dir);
  };
  auto value = [&]() -> WB::Value {
    const double inf = std::numeric_limits<double>::infinity();
    if (k % 4 == 1) return WB::between(std::max(s.lo, v - width), std::min(s.hi, v + width));
    if (k % 4 == 2) {  // one-sided, open away from the special value (or either way inside)
      const bool upper_open = s.target == s.lo || (s.target != s.hi && k % 8 >= 4);
      return upper_open ? WB::between(std::max(s.lo, v - width), inf)
                        : WB::between(-inf, std::min(s.hi, v + width));
    }
    return WB::exactly(v);
  };
  const int count = k % 3 == 2 ? 2 : 1;  // a second special angle on another mobile feature
  for (int i = 0; i < count; ++i) {
    const Vector3d u = r.unit();
    const std::string m = w.mobile(feature(s.mobile, u));
    w.constrain("angle", w.fixed(feature(s.fixed, fixedDirectionFor(s, u, v, r))), m, value());
  }
  if (k % 3 == 1) w.addGeneric();
}

// --- cylinders ---------------------------------------------------------------------------------

void pointOnTwoCylinders(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit(), d2 = tilt(d, a, r);
  const std::string m = w.mobile(F::makePoint(A));
  for (const Vector3d& dd : {d, d2}) {
    const double R = r.uniform(0.2, 1.2);
    w.constrain(
        "coincident",
        w.fixed(F::makeCylinder(A + R * r.perpendicular(dd) + r.uniform(-1, 1) * dd, dd, R)), m);
  }
  if (k % 2) w.addGeneric();
}

void pointOnTwoCoaxialCylinders(WB& w, double gap, int k) {
  Rng& r = w.rng();
  const Vector3d A = r.point(), d = r.unit();
  const double R = r.uniform(0.2, 1.2);
  const Vector3d B1 = A + R * r.perpendicular(d), B2 = B1 + gap * r.perpendicular(d);
  const std::string m = w.mobile(F::makePoint(A));
  for (const Vector3d& B : {B1, B2}) {
    const double radius = (A - B).cross(d).norm();
    w.constrain("coincident", w.fixed(F::makeCylinder(B + r.uniform(-1, 1) * d, d, radius)), m);
  }
  if (k % 2) w.addGeneric();
}

// A line touching a cylinder (or at a skew distance from its axis) nearly parallel to the axis:
// turned by a within the tangent plane at the contact point, it stays tangent.
void lineAlongCylinder(WB& w, double a, int k) {
  Rng& r = w.rng();
  const Vector3d B = r.point(), d = r.unit(), out = r.perpendicular(d);
  const double R = r.uniform(0.2, 1.2);
  const Vector3d A = B + R * out, e = Eigen::AngleAxisd(a, out) * d;
  const std::string m = w.mobile(F::makeLine(A + r.uniform(-1, 1) * e, e));
  if (k % 2 == 0)
    w.constrain("tangent", w.fixed(F::makeCylinder(B + r.uniform(-1, 1) * d, d, R)), m);
  else
    w.constrain("distance", w.fixed(F::makeLine(B + r.uniform(-1, 1) * d, d)), m, WB::exactly(R),
                Orientation::kAligned, false);
  if (k % 4 >= 2) w.addGeneric();
}

}  // namespace

const std::vector<DegenerateFamily>& degenerateFamilies() {
  static const std::vector<DegenerateFamily> all = [] {
    using K = FeatureKind;
    std::vector<DegenerateFamily> f = {
        family("point on two lines meeting at an angle", "angle", kAngles, byAngle,
               pointOnTwoLines),
        family("point on two planes an angle from parallel", "angle", kAngles, byAngle,
               pointOnTwoPlanes),
        family("line in two planes an angle apart", "angle", kAngles, byAngle, lineInTwoPlanes),
        family("two plane contacts an angle from parallel", "angle", kAngles, byAngle,
               twoPlaneContacts),
        family("two line coincidences meeting at an angle", "angle", kAngles, byAngle,
               twoLineCoincidences),
        family("two parallels an angle apart", "angle", kAngles, byAngle, twoParallels),
        family("two point coincidences a gap apart", "gap", kGaps, byAngle, twoPointsApart),
        family("three points a gap off collinear", "gap", kGaps, byAngle,
               threePointsNearlyCollinear),
        family("point on two spheres with centres a gap apart", "gap", kGaps, byAngle,
               nearlyConcentricSpheres),
        family("sphere touching a plane", "eta", kTouch, byTouch, sphereTouchingPlane, 16,
               touchSlack),
        family("sphere touching a line", "eta", kTouch, byTouch, sphereTouchingLine, 16,
               touchSlack),
        family("spheres touching outside", "eta", kTouch, byTouch, spheresTouchingOutside, 16,
               touchSlack),
        family("spheres touching inside", "eta", kTouch, byTouch, spheresTouchingInside, 16,
               touchSlack),
        family("sphere touching a cylinder", "eta", kTouch, byTouch, sphereTouchingCylinder, 16,
               touchSlack),
        family(
            "sphere within tolerance of a plane, points a gap apart", "gap/tolerance",
            {0.5, 0.9, 0.99}, [](double) { return 3e-4; }, sphereWithinToleranceOfPlane, 16,
            [](double) { return 1e-9; }),
        family("two cones with axes an angle apart", "angle", kAngles, byAngle, twoConesApart),
        family("point on two cylinders an angle from parallel", "angle", kAngles, byAngle,
               pointOnTwoCylinders),
        family("point on two parallel cylinders with axes a gap apart", "gap", kGaps, byAngle,
               pointOnTwoCoaxialCylinders),
        // Larger angles only: the skew distance of SPEC (|(a₂ − a₁)·(d̂₁ × d̂₂)| / ‖d̂₁ × d̂₂‖)
        // loses 1/θ of its digits to rounding in the evaluator itself (and in the data), 1e-9
        // of the size at θ = 1e-7; below that no exact known pose can be written down.
        family("line along a cylinder at an angle from its axis", "angle", {1e-4, 1e-5, 1e-6, 1e-7},
               byAngle, lineAlongCylinder, 16,
               [](double a) { return std::max(1e-12, 64 * kEps / a); }),
    };
    // Angles within ε of 0, π/2, π (line–line, plane–plane) and −π/2, 0, π/2 (line–plane, either
    // role), exact and as ranges.
    const std::vector<double> offsets = {0.0, 1e-12, 1e-10, 1e-9};
    const struct {
      const char* label;
      K fixed, mobile;
      double lo, hi;
    } pairs[] = {{"line-line", K::kLine, K::kLine, 0.0, kPi},
                 {"plane(f)-line(m)", K::kPlane, K::kLine, -kPi / 2, kPi / 2},
                 {"line(f)-plane(m)", K::kLine, K::kPlane, -kPi / 2, kPi / 2},
                 {"plane-plane", K::kPlane, K::kPlane, 0.0, kPi}};
    for (const auto& p : pairs)
      for (double target : {p.lo, (p.lo + p.hi) / 2, p.hi}) {
        const SpecialAngle s{p.fixed, p.mobile, target, p.lo, p.hi};
        char label[96];
        std::snprintf(label, sizeof label, "angle %s near %+.4f", p.label, target);
        f.push_back(family(
            label, "offset", offsets, fixedTolerance,
            [s](WB& w, double eps, int k) { specialAngle(s, w, eps, k); }, 24));
      }
    return f;
  }();
  return all;
}

}  // namespace relpos::test
