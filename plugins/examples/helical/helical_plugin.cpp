// Example plugin (b): a manifold type with its matcher, and the constraint type and fundamental
// kind that lead to it.
//
// `thread` (fixed line or cylinder axis, mobile line, value = pitch: advance per full turn,
// positive for a right-handed thread): the mobile line runs along the fixed one, same direction,
// and turning by θ advances it pitch·θ/2π — threaded insertion. With R0 the shortest rotation
// taking the mobile direction onto the fixed one, the poses are R = Rot(d, θ) R0 with the mobile
// line's point at q + (pitch θ / 2π) d, θ any real number.
//
// It decomposes into the parallelism (so other angle constraints combine with it) and a `helical`
// fundamental of this plugin's own kind, which only this plugin's matcher understands. The
// index of that kind is this plugin's state: the registry keeps it (Registry::keep) and hands it
// to the callbacks as their context, so two registries loading the plugin keep their own.
#include <cmath>

#include "helical_manifold.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/core/plugin_api.hpp"
#include "relpos/core/solution.hpp"

namespace helical_plugin {
using namespace relpos;

// What the callbacks share: the registry's index of the `helical` kind.
struct Helical {
  std::uint16_t kind;
};
const Helical& helical(const void* context) { return *static_cast<const Helical*>(context); }

void checkThread(const InputConstraint& c, std::vector<std::string>& problems, const void*) {
  if (!c.has_value) problems.push_back("value: a thread needs its pitch as \"value\", not a range");
}

void decomposeThread(const InputConstraint& c, const Feature& F, SourceMask s, Decomposition& out,
                     const void* context) {
  auto& alt = out.addAlternative();
  alt.push_back(Fundamental::angle(c.mobile.direction, F.direction, 0.0, s));
  Fundamental h;
  h.kind = FundamentalKind::kCustom;
  h.custom = helical(context).kind;
  h.point_side = Side::kMobile;
  h.p = c.mobile.point;
  h.u = c.mobile.direction.normalized();
  h.q = F.point;
  h.d = F.direction.normalized();
  h.lo = h.hi = c.value;
  h.sources = s;
  alt.push_back(h);
}

// Written from the definition above, not from the manifold: the larger of the direction error
// (radians), the distance of the mobile point from the axis, and the advance's distance from the
// nearest advance the turn allows.
double helicalResidual(const Fundamental& f, const Isometry3d& X, const void*) {
  const Vector3d u = X.linear() * f.u;
  const double direction_error = std::atan2(u.cross(f.d).norm(), u.dot(f.d));
  const Vector3d w = X * f.p - f.q;
  const double off_axis = (w - w.dot(f.d) * f.d).norm();
  const Matrix3d D = X.linear() * screwBase(f.u, f.d).transpose();
  const Vector3d e = anyPerpendicular(f.d), g = D * e;
  const double phi = std::atan2(f.d.dot(e.cross(g)), e.dot(g));
  const double pitch = f.lo;
  const double drift = w.dot(f.d) - pitch * phi / (2 * kPi);
  const double phase_error =
      pitch == 0.0 ? std::abs(drift) : std::abs(drift - pitch * std::round(drift / pitch));
  return std::max(direction_error, std::max(off_axis, phase_error));
}

MatchResult matchHelical(MatchContext& ctx, const void* context) {
  const auto& ts = ctx.set.translational;
  const auto& rs = ctx.set.rotational;
  if (ts.size() != 1 || ts[0].kind != FundamentalKind::kCustom ||
      ts[0].custom != helical(context).kind)
    return MatchResult::kNoMatch;
  const Fundamental& h = ts[0];
  // Exactly the thread's own parallelism (anything more is not a screw motion we know).
  if (rs.size() != 1 || !rs[0].exact() || !ctx.tol.zeroAngle(rs[0].value()) ||
      rs[0].p.cross(h.u).norm() > ctx.tol.angle || rs[0].p.dot(h.u) < 0 ||
      rs[0].q.cross(h.d).norm() > ctx.tol.angle || rs[0].q.dot(h.d) < 0)
    return MatchResult::kNoMatch;
  if (!ctx.branches.add<HelicalManifold>(h.p, h.u, h.q, h.d, h.lo)) return MatchResult::kOverflow;
  return MatchResult::kMatched;
}

void registerAll(Registry& registry) {
  CustomKindInfo kind;
  kind.name = "helical";
  kind.description = "a screw motion: along a fixed axis, advancing pitch per turn";
  kind.residual = &helicalResidual;
  const Helical* state = registry.keep(Helical{registry.addCustomKind(kind)});
  ConstraintType t;
  t.name = "thread";
  t.description =
      "line(f)-line(m), cylinder(f)-line(m): the mobile line screws along the fixed axis, "
      "advancing `value` (the pitch) per full turn";
  t.accepts = {{FeatureKind::kLine, FeatureKind::kLine},
               {FeatureKind::kCylinder, FeatureKind::kLine}};
  t.takes_value = true;
  t.check = &checkThread;
  t.decompose = &decomposeThread;
  t.context = state;
  registry.addConstraintType(t);
  registry.addManifold({"Helical", "1 DOF: a screw motion about a fixed axis (thread plugin)"});
  MatcherInfo matcher;
  matcher.name = "helical";
  matcher.fn = &matchHelical;
  matcher.context = state;
  registry.addMatcher(matcher);
}

}  // namespace helical_plugin

RELPOS_PLUGIN(helical_plugin::registerAll)
