// A problem whose mobile features all lie on one line as a LineFamily member
// (problem_encoding.hpp): the line's world direction w and foot q are the unknowns; the spin
// about the line and the slide along it stay exact parameters of the branches.
#include <cmath>

#include "encoding_support.hpp"
#include "relpos/complete/problem_encoding.hpp"

namespace relpos::complete {
namespace {

using detail::Slots;
using FK = FeatureKind;
using L = LineEquationKind;

bool onLine(FK k) { return k == FK::kLine || k == FK::kCylinder; }

// The first mobile line (or axis) of the constraints in their canonical order (the same for a
// permutation of them).
const Feature* referenceLine(const Problem& problem) {
  for (const int i : detail::canonicalOrder(problem))
    if (onLine(problem.constraints[i].mobile.kind)) return &problem.constraints[i].mobile;
  return nullptr;
}

}  // namespace

bool mobileFeaturesOnOneLine(const Problem& problem, const Tolerance& tol) {
  const Feature* ref = referenceLine(problem);
  if (!ref) return false;
  for (const InputConstraint& c : problem.constraints) {
    if (!onLine(c.mobile.kind)) return false;
    if (!tol.parallelUnit(c.mobile.direction.cross(ref->direction).norm())) return false;
    if (!tol.zeroLength((c.mobile.point - ref->point).cross(ref->direction).norm())) return false;
  }
  return true;
}

bool encodeLine(const Problem& problem, const Tolerance& tol, LineEncoding* out, std::string* why) {
  *out = LineEncoding{};
  if (!mobileFeaturesOnOneLine(problem, tol)) {
    *why = "the mobile features are not on one line";
    return false;
  }
  const Feature& ref = *referenceLine(problem);
  out->mobile_point = ref.point;
  out->mobile_direction = ref.direction;
  out->frames = detail::normalisationOf(problem);
  out->equations = {{L::kUnit, -1, -1}, {L::kFoot, -1, -1}};
  Slots slots(&out->target);
  auto push = [&](L kind, int fixed, double value) {
    out->equations.push_back({kind, fixed, slots.value(value)});
  };
  auto point = [&](const Vector3d& p) { return slots.shared(Slots::kFixed, Slots::kPoint, p); };
  auto dir = [&](const Vector3d& u) { return slots.shared(Slots::kFixed, Slots::kDirection, u); };
  for (const int i : detail::canonicalOrder(problem)) {
    const InputConstraint& c = problem.constraints[i];
    const std::string at = "constraint " + std::to_string(i) + ": ";
    if (!detail::isEncodedType(c.type) || (c.isRange() && c.min != c.max)) {
      *why = at + "not a built-in constraint with an exact value";
      return false;
    }
    const double value = c.has_value ? c.value : c.min;
    InputConstraint exact = c;
    exact.has_value = true, exact.value = value;
    const detail::NormalisedConstraint n = detail::normalised(problem, exact, out->frames);
    const Feature& F = n.fixed;
    const FK f = F.kind;
    // The mobile direction is s·(the reference direction): w is the reference's in the world.
    const double s = c.mobile.direction.dot(ref.direction) > 0.0 ? 1.0 : -1.0;
    auto parallel = [&](const Vector3d& u, Orientation o) {
      Vector3d nk[2];
      detail::normalsAcross(u, &nk[0], &nk[1]);
      for (const Vector3d& v : nk) push(L::kDirection, slots.unique(v), 0.0);
      if (o != Orientation::kEither)
        out->signs.push_back({u, s * ref.direction, o == Orientation::kAligned ? 1.0 : -1.0});
    };
    const bool cylinder = c.mobile.kind == FK::kCylinder;
    bool ok = false;
    if (c.type == "distance" && !cylinder) {
      if (f == FK::kPoint && n.value != 0.0) {
        push(L::kPointDistance, point(F.point), n.value * n.value), ok = true;
      } else if (f == FK::kPlane) {  // d·n = 0 and the line at signed distance v
        push(L::kDirection, dir(F.direction), 0.0);
        push(L::kPlaneOffset, dir(F.direction), n.value + F.direction.dot(F.point)), ok = true;
      } else if (f == FK::kLine && c.parallel && n.value != 0.0) {
        parallel(F.direction, c.orientation);
        push(L::kPointDistance, point(F.point), n.value * n.value), ok = true;
      }
    } else if (c.type == "coincident") {
      if (f == FK::kPoint && cylinder) {
        push(L::kPointDistance, point(F.point), n.mobile.radius * n.mobile.radius), ok = true;
      } else if (f == FK::kPlane && !cylinder) {
        push(L::kDirection, dir(F.direction), 0.0);
        push(L::kPlaneOffset, dir(F.direction), F.direction.dot(F.point)), ok = true;
      }
    } else if (c.type == "angle" && !cylinder) {
      const bool same = f == FK::kLine;
      const double kappa = same ? std::cos(value) : std::sin(value);
      const bool zero = detail::angleAt(value, 0.0);
      if (same && (zero || detail::angleAt(value, kPi))) {
        parallel(F.direction, zero ? Orientation::kAligned : Orientation::kOpposed), ok = true;
      } else if (!same && detail::angleAt(std::abs(value), kPi / 2)) {
        parallel(F.direction, value > 0 ? Orientation::kAligned : Orientation::kOpposed), ok = true;
      } else {
        push(L::kDirection, dir(F.direction), s * kappa), ok = true;
      }
    } else if (c.type == "parallel" && !cylinder) {
      if (f == FK::kLine) parallel(F.direction, c.orientation), ok = true;
      if (f == FK::kPlane) push(L::kDirection, dir(F.direction), 0.0), ok = true;
    } else if (c.type == "perpendicular" && !cylinder) {
      if (f == FK::kLine) push(L::kDirection, dir(F.direction), 0.0), ok = true;
      if (f == FK::kPlane) parallel(F.direction, c.orientation), ok = true;
    } else if (c.type == "tangent" && cylinder) {
      const double r = n.mobile.radius;
      if (f == FK::kPlane && c.orientation != Orientation::kEither) {
        // The axis in the plane's direction at signed distance −r (aligned) or +r (opposed).
        const double d = c.orientation == Orientation::kAligned ? -r : r;
        push(L::kDirection, dir(F.direction), 0.0);
        push(L::kPlaneOffset, dir(F.direction), d + F.direction.dot(F.point)), ok = true;
      } else if (f == FK::kCylinder) {  // axes parallel either way, r₁ + r₂ apart
        parallel(F.direction, Orientation::kEither);
        push(L::kPointDistance, point(F.point), (F.radius + r) * (F.radius + r)), ok = true;
      }
    }
    if (!ok) {
      *why = at + "'" + c.type + "' " + toString(f) + "-" + toString(c.mobile.kind) +
             " is not encoded on a line";
      return false;
    }
  }
  const int n = static_cast<int>(out->equations.size()) - 2;
  int directional = 0;  // equations on the direction alone
  for (const LineEquation& q : out->equations) directional += q.kind == L::kDirection;
  if (n == 4 && directional > 2) {
    *why = std::to_string(directional) +
           " equations on the line's direction alone (2 unknowns): not isolated lines";
    return false;
  }
  if (n != 4) {
    *why = "the constraints give " + std::to_string(n) +
           " equations on the line (4 unknowns): not isolated lines";
    return false;
  }
  return true;
}

}  // namespace relpos::complete
