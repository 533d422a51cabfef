// The constraint types of docs/spec.md §1 and their decomposition into fundamental constraints
// (PMF Table I). Fixed geometry arrives in world coordinates, mobile geometry in the mobile frame.
#include <algorithm>
#include <cmath>
#include <string>

#include "constraint_violation.hpp"
#include "relpos/rules/builtin.hpp"

namespace relpos::rules {
namespace {

using K = FeatureKind;
using Alt = FixedVector<Fundamental, 4>;

bool isPointKind(K k) { return k == K::kPoint; }

// Adds the rotational part of "directions parallel per orientation": one alternative per allowed
// orientation (aligned: angle 0, opposed: angle π). Each alternative receives `extra` too.
void parallelAlternatives(Orientation o, const Vector3d& u_m, const Vector3d& u_f, SourceMask s,
                          const Fundamental* extra, Decomposition& out) {
  if (o != Orientation::kOpposed) {
    Alt& a = out.addAlternative();
    a.push_back(Fundamental::angle(u_m, u_f, 0.0, s));
    if (extra) a.push_back(*extra);
  }
  if (o != Orientation::kAligned) {
    Alt& a = out.addAlternative();
    a.push_back(Fundamental::angle(u_m, u_f, kPi, s));
    if (extra) a.push_back(*extra);
  }
}

void single(Decomposition& out, const Fundamental& f) { out.addAlternative().push_back(f); }
void pair(Decomposition& out, const Fundamental& f, const Fundamental& g) {
  Alt& a = out.addAlternative();
  a.push_back(f);
  a.push_back(g);
}

// Point–X distance v with either role order: d(P_m, X_f) or d(P_f, X_m).
Fundamental pointDistance(const Feature& F, const Feature& M, double v, SourceMask s) {
  const bool point_mobile = isPointKind(M.kind);
  const Feature& P = point_mobile ? M : F;
  const Feature& X = point_mobile ? F : M;
  const Side side = point_mobile ? Side::kMobile : Side::kFixed;
  switch (X.kind) {
    case K::kPoint:
      return Fundamental::pointPoint(M.point, F.point, v, s);
    case K::kLine:
      return Fundamental::pointLine(side, P.point, X.point, X.direction, v, s);
    case K::kCylinder:  // point on a cylinder: distance to its axis (SPEC coincident)
      return Fundamental::pointLine(side, P.point, X.point, X.direction, v, s);
    case K::kPlane:
    default:
      return Fundamental::pointPlane(side, P.point, X.point, X.direction, v, s);
  }
}

// Signed offset of a line (or plane) point from a plane: the point lies on the plane shifted by v.
Fundamental onOffsetPlane(const Feature& F, const Feature& M, double v, SourceMask s) {
  // The plane belongs to whichever side is a plane; the other side contributes its support point.
  const bool plane_fixed = F.kind == K::kPlane;
  const Feature& Pl = plane_fixed ? F : M;
  const Feature& O = plane_fixed ? M : F;
  return Fundamental::pointPlane(plane_fixed ? Side::kMobile : Side::kFixed, O.point, Pl.point,
                                 Pl.direction, v, s);
}

void decomposeDistanceValue(const InputConstraint& c, const Feature& F, SourceMask s, double v,
                            Decomposition& out);

// A min/max range that is not a single value.
bool isProperRange(const InputConstraint& c) { return c.isRange() && c.min != c.max; }

// Somani Table III: a range on a distance bounds the translational fundamental constraint (the
// rotational part stays exact). Point-plane ranges keep their plane unshifted and carry the signed
// range; unsigned distances start at 0.
void applyRange(const InputConstraint& c, Decomposition& out) {
  for (auto& alt : out.alternatives)
    for (Fundamental& f : alt) {
      if (!f.translational()) continue;
      const bool is_signed = f.kind == FundamentalKind::kPointPlane;
      f.lo = is_signed ? c.min : std::max(0.0, c.min);
      f.hi = c.max;
    }
}

void decomposeDistance(const InputConstraint& c, const Feature& F, SourceMask s, Decomposition& out,
                       const void* /*context*/) {
  const bool range = isProperRange(c);
  if (F.kind == K::kLine && c.mobile.kind == K::kLine && !c.parallel) {
    // Somani's mixed constraint: the skew distance between the lines, no parallelism required.
    const double lo = range ? std::max(0.0, c.min) : (c.has_value ? c.value : c.min);
    const double hi = range ? c.max : lo;
    return single(out, Fundamental::lineLine(c.mobile.point, c.mobile.direction, F.point,
                                             F.direction, lo, hi, s));
  }
  decomposeDistanceValue(c, F, s, range ? 0.0 : (c.has_value ? c.value : c.min), out);
  if (range && !out.unhandled) applyRange(c, out);
}

void decomposeDistanceValue(const InputConstraint& c, const Feature& F, SourceMask s, double v,
                            Decomposition& out) {
  const Feature& M = c.mobile;
  if (isPointKind(F.kind) || isPointKind(M.kind)) return single(out, pointDistance(F, M, v, s));
  if (F.kind == K::kLine && M.kind == K::kLine) {
    // Table I: d(L_a, L_b) = p -> d(R_a, L_b) = p and the lines parallel.
    Fundamental t = Fundamental::pointLine(Side::kMobile, M.point, F.point, F.direction, v, s);
    return parallelAlternatives(c.orientation, M.direction, F.direction, s, &t, out);
  }
  if (F.kind == K::kPlane && M.kind == K::kPlane) {
    // Table I: d(Π_a, Π_b) = p -> d(S_a, Υ_b) = 0 and the normals parallel. The distance is
    // measured along the fixed normal (SPEC), so the mobile plane's point goes on the fixed plane.
    Fundamental t = Fundamental::pointPlane(Side::kMobile, M.point, F.point, F.direction, v, s);
    return parallelAlternatives(c.orientation, M.direction, F.direction, s, &t, out);
  }
  // line–plane (either role): d·n = 0 and the line's point at signed distance v.
  const Vector3d& u_m = M.direction;
  const Vector3d& u_f = F.direction;
  pair(out, onOffsetPlane(F, M, v, s), Fundamental::angle(u_m, u_f, kPi / 2, s));
}

void decomposeAngle(const InputConstraint& c, const Feature& F, SourceMask s, Decomposition& out,
                    const void* /*context*/) {
  const bool line_plane = F.kind != c.mobile.kind;
  // Table I: ∠(L, Π) = α -> ∠(d, n) = π/2 − α; the others compare directions directly. A range
  // maps the same way (Somani Table III: OneAngleMinMax), clamped to [0, π].
  auto map = [&](double v) { return line_plane ? kPi / 2 - v : v; };
  if (!isProperRange(c)) {
    const double v = c.has_value ? c.value : c.min;
    return single(out, Fundamental::angle(c.mobile.direction, F.direction, map(v), s));
  }
  const double a = map(c.min), b = map(c.max);
  Fundamental f = Fundamental::angle(c.mobile.direction, F.direction, 0.0, s);
  f.lo = std::max(0.0, std::min(a, b));
  f.hi = std::min(kPi, std::max(a, b));
  single(out, f);
}

void decomposeCoincident(const InputConstraint& c, const Feature& F, SourceMask s,
                         Decomposition& out, const void* /*context*/) {
  const Feature& M = c.mobile;
  if (isPointKind(F.kind) || isPointKind(M.kind)) {
    const Feature& X = isPointKind(M.kind) ? F : M;
    return single(out, pointDistance(F, M, X.kind == K::kCylinder ? X.radius : 0.0, s));
  }
  if (F.kind == K::kLine && M.kind == K::kLine) {
    Fundamental t = Fundamental::pointLine(Side::kMobile, M.point, F.point, F.direction, 0, s);
    return parallelAlternatives(c.orientation, M.direction, F.direction, s, &t, out);
  }
  if (F.kind == K::kPlane && M.kind == K::kPlane) {
    Fundamental t = Fundamental::pointPlane(Side::kMobile, M.point, F.point, F.direction, 0, s);
    return parallelAlternatives(c.orientation, M.direction, F.direction, s, &t, out);
  }
  // line in plane
  pair(out, onOffsetPlane(F, M, 0.0, s), Fundamental::angle(M.direction, F.direction, kPi / 2, s));
}

void decomposeParallel(const InputConstraint& c, const Feature& F, SourceMask s, Decomposition& out,
                       const void* /*context*/) {
  if (F.kind != c.mobile.kind)  // line ∥ plane: d ⊥ n
    return single(out, Fundamental::angle(c.mobile.direction, F.direction, kPi / 2, s));
  parallelAlternatives(c.orientation, c.mobile.direction, F.direction, s, nullptr, out);
}

void decomposePerpendicular(const InputConstraint& c, const Feature& F, SourceMask s,
                            Decomposition& out, const void* /*context*/) {
  if (F.kind != c.mobile.kind)  // line ⊥ plane: d ∥ n per orientation
    return parallelAlternatives(c.orientation, c.mobile.direction, F.direction, s, nullptr, out);
  single(out, Fundamental::angle(c.mobile.direction, F.direction, kPi / 2, s));
}

void decomposeTangent(const InputConstraint& c, const Feature& F, SourceMask s, Decomposition& out,
                      const void* /*context*/) {
  const Feature& M = c.mobile;
  if (F.kind == K::kCylinder && M.kind == K::kCylinder) {
    // Axes parallel either way, at distance r1 + r2.
    Fundamental t = Fundamental::pointLine(Side::kMobile, M.point, F.point, F.direction,
                                           F.radius + M.radius, s);
    return parallelAlternatives(Orientation::kEither, M.direction, F.direction, s, &t, out);
  }
  if (F.kind == K::kLine || M.kind == K::kLine) {
    // The line touches the surface: the skew distance between axis and line is the radius
    // (a mixed constraint, Somani 004 §IV-A).
    const double r = F.kind == K::kCylinder ? F.radius : M.radius;
    return single(out, Fundamental::lineLine(M.point, M.direction, F.point, F.direction, r, r, s));
  }
  // cylinder–plane: axis ∥ plane, signed axis distance −r (aligned) or +r (opposed).
  const Feature& cyl = F.kind == K::kCylinder ? F : M;
  const Fundamental angle = Fundamental::angle(M.direction, F.direction, kPi / 2, s);
  for (Orientation o : {Orientation::kAligned, Orientation::kOpposed}) {
    if (c.orientation != Orientation::kEither && c.orientation != o) continue;
    const double v = o == Orientation::kAligned ? -cyl.radius : cyl.radius;
    pair(out, onOffsetPlane(F, M, v, s), angle);
  }
}

// ---- value checks ------------------------------------------------------------------------------

void checkFinite(const InputConstraint& c, std::vector<std::string>& problems) {
  if (c.has_value && !std::isfinite(c.value)) problems.push_back("value: not a finite number");
}

bool signedDistance(const InputConstraint& c) {
  // Signed: point–plane, line–plane, plane–plane (SPEC table).
  return c.fixed.kind == K::kPlane || c.mobile.kind == K::kPlane;
}

void checkDistance(const InputConstraint& c, std::vector<std::string>& problems,
                   const void* /*context*/) {
  checkFinite(c, problems);
  if (signedDistance(c)) return;
  auto neg = [&](const char* field, double v) {
    if (v < 0)
      problems.push_back(std::string(field) + ": negative value " + std::to_string(v) +
                         " for an unsigned distance");
  };
  if (c.has_value) neg("value", c.value);
  if (!c.has_value && std::isfinite(c.min)) neg("min", c.min);
  if (!c.has_value && std::isfinite(c.max)) neg("max", c.max);
}

void checkAngle(const InputConstraint& c, std::vector<std::string>& problems,
                const void* /*context*/) {
  checkFinite(c, problems);
  const bool line_plane = c.fixed.kind != c.mobile.kind;
  const double lo = line_plane ? -kPi / 2 : 0.0, hi = line_plane ? kPi / 2 : kPi;
  const char* range = line_plane ? "[-pi/2, pi/2]" : "[0, pi]";
  auto check = [&](const char* field, double v) {
    if (std::isfinite(v) && (v < lo - kAngleRangeSlack || v > hi + kAngleRangeSlack))
      problems.push_back(std::string(field) + ": angle " + std::to_string(v) + " rad is outside " +
                         range);
  };
  if (c.has_value)
    check("value", c.value);
  else
    check("min", c.min), check("max", c.max);
}

std::vector<FeaturePair> pairs(std::initializer_list<FeaturePair> l) { return l; }

}  // namespace

void registerBuiltinConstraintTypes(Registry& r) {
  const K P = K::kPoint, L = K::kLine, Pl = K::kPlane, C = K::kCylinder;
  ConstraintType t;
  t.name = "distance";
  t.description = "distance between point/line/plane features (PMF Table I)";
  t.accepts = pairs({{P, P}, {P, L}, {L, P}, {P, Pl}, {Pl, P}, {L, L}, {L, Pl}, {Pl, L}, {Pl, Pl}});
  t.takes_value = true;
  t.value_kind = ValueKind::kLength;
  t.parallel_on = pairs({{L, L}});
  t.check = &checkDistance;
  t.decompose = &decomposeDistance;
  t.violation = &distanceViolation;
  r.addConstraintType(t);

  t = ConstraintType{};
  t.name = "angle";
  t.description = "angle between line directions and plane normals (PMF Table I)";
  t.accepts = pairs({{L, L}, {L, Pl}, {Pl, L}, {Pl, Pl}});
  t.takes_value = true;
  t.value_kind = ValueKind::kAngle;
  t.check = &checkAngle;
  t.decompose = &decomposeAngle;
  t.violation = &angleViolation;
  r.addConstraintType(t);

  t = ConstraintType{};
  t.name = "coincident";
  t.description = "coincidence / containment (distance 0; point on cylinder: distance r to axis)";
  t.accepts = pairs({{P, P},
                     {P, L},
                     {L, P},
                     {P, Pl},
                     {Pl, P},
                     {L, L},
                     {L, Pl},
                     {Pl, L},
                     {Pl, Pl},
                     {P, C},
                     {C, P}});
  t.decompose = &decomposeCoincident;
  t.violation = &coincidentViolation;
  r.addConstraintType(t);

  t = ConstraintType{};
  t.name = "parallel";
  t.description = "parallel directions / normals; line parallel to plane";
  t.accepts = pairs({{L, L}, {Pl, Pl}, {L, Pl}, {Pl, L}});
  t.decompose = &decomposeParallel;
  t.violation = &parallelViolation;
  r.addConstraintType(t);

  t = ConstraintType{};
  t.name = "perpendicular";
  t.description = "perpendicular directions / normals; line along a plane's normal";
  t.accepts = pairs({{L, L}, {Pl, Pl}, {L, Pl}, {Pl, L}});
  t.decompose = &decomposePerpendicular;
  t.violation = &perpendicularViolation;
  r.addConstraintType(t);

  t = ConstraintType{};
  t.name = "tangent";
  t.description = "cylinder tangent to a plane, a cylinder or a line";
  t.accepts = pairs({{C, Pl}, {Pl, C}, {C, C}, {C, L}, {L, C}});
  t.decompose = &decomposeTangent;
  t.violation = &tangentViolation;
  r.addConstraintType(t);
}

}  // namespace relpos::rules
