#include "parameter_motion.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

namespace relpos {

namespace detail {
namespace {

// The twist of X(θ) along parameter i: the world angular velocity ω and the velocity ṗ of the
// mobile origin. Central differences of step h within the bounds (a bound reached: one-sided);
// an error of O(h²), 1e-12 relative, far below what the motion is used for.
bool twist(const Manifold& m, const Params& at, int i, Vector3d* omega, Vector3d* pdot) {
  const Parameter p = m.parameter(i);
  const double h = 1e-6 * (1.0 + std::abs(at[i]));
  Params a = at, b = at;
  a[i] = at[i] - h;
  b[i] = at[i] + h;
  if (!p.periodic) a[i] = std::max(a[i], p.min), b[i] = std::min(b[i], p.max);
  const double span = b[i] - a[i];
  if (!(span > 0.5 * h)) return false;  // a parameter pinned by its bounds
  const Isometry3d Xa = m.pose(a), Xb = m.pose(b);
  const Eigen::AngleAxisd turn(Matrix3d(Xb.linear() * Xa.linear().transpose()));
  *omega = turn.axis() * (turn.angle() / span);
  *pdot = (Xb.translation() - Xa.translation()) / span;
  return omega->allFinite() && pdot->allFinite();
}

ParameterMotion motionOf(const Vector3d& omega, const Vector3d& pdot, const Vector3d& origin,
                         double scale) {
  ParameterMotion mo;
  const double w = omega.norm();
  // Below these a motion is rounding: 1e-9 rad or length (relative to the problem's size) per
  // unit of the parameter against the 1e-12 of the differences.
  if (w < 1e-9) {
    const double v = pdot.norm();
    if (v < 1e-9 * scale) return mo;
    mo.type = ParameterMotion::Type::kTranslation;
    mo.axis = pdot / v;
    mo.rate = v;
    return mo;
  }
  mo.axis = omega / w;
  mo.rate = w;
  // The velocity of the world point at the mobile origin is ṗ = ω × (origin − q) + pitch·ω for a
  // point q of the axis: q is the origin moved by ω × ṗ / |ω|² (then nearest the origin).
  mo.point = origin + omega.cross(pdot) / (w * w);
  mo.pitch = omega.dot(pdot) / (w * w);
  if (std::abs(mo.pitch) < 1e-9 * scale) {
    mo.type = ParameterMotion::Type::kRotation;
    mo.pitch = 0.0;
  } else {
    mo.type = ParameterMotion::Type::kScrew;
  }
  return mo;
}

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
  const Vector3d origin = m.pose(at).translation();
  const double scale = std::max(1.0, problem.lengthScale());
  for (int i = 0; i < m.dof(); ++i) {
    ParameterMotion& mo = out[static_cast<std::size_t>(i)];
    Vector3d omega, pdot;
    ParameterMotion found;
    // A plugin's pose function that throws beside the nearest pose leaves the motion unknown;
    // the stage that needs those poses (samples, the collision filter) reports it.
    try {
      if (twist(m, at, i, &omega, &pdot)) found = motionOf(omega, pdot, origin, scale);
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
