#include "parameter_motion.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>

namespace relpos {

namespace detail {

ParameterMotion screwBetween(const Isometry3d& Xa, const Isometry3d& Xb, double span,
                             const Vector3d& origin, double scale) {
  ParameterMotion mo;
  // Xb = M·Xa with M = [R, t] a rigid motion: a screw (Chasles) of angle φ about a line.
  const Matrix3d R = Xb.linear() * Xa.linear().transpose();
  const Vector3d t = Xb.translation() - R * Xa.translation();
  const Eigen::AngleAxisd turn(R);
  const double phi = turn.angle();
  if (!std::isfinite(phi) || !t.allFinite() || !(span > 0.0)) return mo;
  // Below these a motion is rounding: 1e-9 rad, or 1e-9 of the problem's size, per unit of the
  // parameter, and never below the poses' own rounding (64 ulps of their angles and coordinates).
  constexpr double kUlps = 64 * std::numeric_limits<double>::epsilon();
  const double length_noise = kUlps * (scale + Xa.translation().norm() + Xb.translation().norm());
  if (phi < std::max(1e-9 * span, kUlps)) {
    const double v = t.norm() / span;
    if (!(v >= 1e-9 * scale) || !(t.norm() > length_noise)) return mo;
    mo.type = ParameterMotion::Type::kTranslation;
    mo.axis = t.normalized();
    mo.rate = v;
    return mo;
  }
  const Vector3d a = turn.axis();
  mo.axis = a;
  mo.rate = phi / span;
  // t = (I − R)·q + d·a for a point q of the axis and an advance d along it; in the plane
  // across the axis, q = ½ (t⊥ + cot(φ/2) a × t⊥) (the point the turn leaves in place).
  const double d = t.dot(a);
  const Vector3d perp = t - d * a;
  const Vector3d q = 0.5 * (perp + a.cross(perp) / std::tan(0.5 * phi));
  mo.point = q + (origin - q).dot(a) * a;  // the axis point nearest the origin
  mo.pitch = d / phi;
  if (std::abs(d) < std::max(1e-9 * scale * span, length_noise)) {
    mo.type = ParameterMotion::Type::kRotation;
    mo.pitch = 0.0;
  } else {
    mo.type = ParameterMotion::Type::kScrew;
  }
  return mo;
}

bool stepAround(const Manifold& m, const Params& at, int i, double step, Params* a, Params* b) {
  const Parameter p = m.parameter(i);
  double h = step * (1.0 + std::abs(at[i]));
  // Within a narrow range (a 1° angle range, a 10 mm one in metres): a quarter of it.
  if (!p.periodic && std::isfinite(p.max - p.min)) h = std::min(h, 0.25 * (p.max - p.min));
  *a = at, *b = at;
  (*a)[i] = at[i] - h;
  (*b)[i] = at[i] + h;
  if (!p.periodic) (*a)[i] = std::max((*a)[i], p.min), (*b)[i] = std::min((*b)[i], p.max);
  return (*b)[i] - (*a)[i] > 0.5 * h;
}

ParameterMotion motionAlong(const Manifold& m, const Params& at, const Vector3d& origin, int i,
                            double step, double scale) {
  Params a, b;
  if (!stepAround(m, at, i, step, &a, &b)) return ParameterMotion();  // pinned by its bounds
  return screwBetween(m.pose(a), m.pose(b), b[i] - a[i], origin, scale);
}

namespace {

// The ranged input constraint among the branch's sources whose range parameter this is: a
// parameter named as docs/spec.md §1.10 names them, of the constraint's kind (angle or length),
// one of whose finite bounds is that constraint's (the other may be clipped, §1.10) or whose
// width is; -1 unless exactly one constraint fits.
int rangeConstraint(const Problem& problem, const Branch& branch, const Parameter& p) {
  static const char* const kRangeNames[] = {"distance", "radius", "height", "alpha"};
  bool named = false;
  for (const char* n : kRangeNames) named = named || std::strcmp(p.name, n) == 0;
  if (!named) return -1;
  int found = -1;
  for (std::size_t k = 0; k < problem.constraints.size() && k < 64; ++k) {
    if (!(branch.sources & (SourceMask{1} << k))) continue;
    const InputConstraint& c = problem.constraints[k];
    // An angle parameter spans an angle's range, a length one a distance's.
    if (!c.isRange() || (p.kind == ParamKind::kAngle) != (c.type == "angle")) continue;
    // The same bound, or (an angle range measured from the other side: from a plane's normal
    // rather than the plane) the same width.
    const double width = p.max - p.min, c_width = c.max - c.min;
    const bool fits = (std::isfinite(p.max) && p.max == c.max) ||
                      (std::isfinite(p.min) && p.min == c.min) ||
                      (std::isfinite(width) && std::abs(width - c_width) <= 1e-12 * (1 + width));
    if (!fits) continue;
    if (found >= 0) return -1;  // two ranges alike: not told apart
    found = static_cast<int>(k);
  }
  return found;
}

}  // namespace

void parameterMotions(const Problem& problem, const Branch& branch, const Params& at,
                      std::array<ParameterMotion, kMaxDof>& out) {
  const Manifold& m = *branch.manifold;
  const Vector3d origin = m.pose(at).translation();  // a throw at the nearest pose is let through
  const double scale = std::max(1.0, problem.lengthScale());
  for (int i = 0; i < m.dof(); ++i) {
    ParameterMotion& mo = out[static_cast<std::size_t>(i)];
    ParameterMotion found;
    // A plugin's pose function that throws beside the nearest pose leaves the motion unknown;
    // the stage that needs those poses (samples, the collision filter) reports it.
    try {
      found = motionAlong(m, at, origin, i, 1e-4, scale);
    } catch (const std::exception&) {
      found.type = ParameterMotion::Type::kUnknown;
    }
    mo.type = found.type, mo.axis = found.axis, mo.point = found.point;
    mo.pitch = found.pitch, mo.rate = found.rate;
    mo.constraint = rangeConstraint(problem, branch, m.parameter(i));
    mo.constraint_id.clear();
    if (mo.constraint >= 0) mo.constraint_id = problem.constraints[mo.constraint].id;
  }
}

}  // namespace detail
}  // namespace relpos
