// The mixed-manifold matcher (Somani 004 §IV-A): sets whose constraints cannot be split into a
// rotational and a translational part. Today: one line-line distance (skew, or a cylinder-line
// tangency) on its own, and the radial grasp. (Revolved branches come from the separable
// matcher, which derives their inner fixed-rotation sets.)
#include <utility>

#include "relpos/core/branch_sink.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/manifolds/builtin.hpp"
#include "relpos/manifolds/catalogue.hpp"
#include "relpos/manifolds/line_distance.hpp"
#include "relpos/manifolds/radial_grasp.hpp"

namespace relpos::manifolds {
namespace {

// Unit vectors along one line (either way), within the angle tolerance.
bool alongSameLine(const Vector3d& a, const Vector3d& b, const Tolerance& tol) {
  return tol.parallelUnit(a.cross(b).norm());
}

// The radial grasp (Somani 004 §VI-C, D): the approach line meets the axis (skew distance 0) at a
// right angle, the fingertip on the approach line at a distance (range) from the axis, and
// optionally at a height (range) along it. Returns false unless the set is exactly that.
bool radialGrasp(const ConstraintSet& set, const Tolerance& tol, RadialGraspSpec* spec) {
  const Fundamental* ll = nullptr;
  const Fundamental* pl = nullptr;
  const Fundamental* pp = nullptr;
  for (const auto& f : set.translational) {
    const Fundamental** slot = f.kind == FundamentalKind::kLineLine     ? &ll
                               : f.kind == FundamentalKind::kPointLine  ? &pl
                               : f.kind == FundamentalKind::kPointPlane ? &pp
                                                                        : nullptr;
    if (!slot || *slot) return false;
    *slot = &f;
  }
  if (!ll || !pl || set.rotational.size() != 1) return false;
  const Fundamental& a = set.rotational[0];
  if (!ll->exact() || !tol.zeroLength(ll->lo) || !a.exact() ||
      !tol.equalAngle(a.value(), kPi / 2) || !alongSameLine(a.p, ll->u, tol) ||
      !alongSameLine(a.q, ll->d, tol))
    return false;
  // The fingertip's distance is measured from the same axis, and the tip is on the approach line.
  const Vector3d w = pl->q - ll->q;
  if (pl->point_side != Side::kMobile || !alongSameLine(pl->d, ll->d, tol) ||
      (w - w.dot(ll->d) * ll->d).norm() > tol.length ||
      (pl->p - ll->p).cross(ll->u).norm() > tol.length)
    return false;
  if (pp && (pp->point_side != Side::kMobile || (pp->p - pl->p).norm() > tol.length ||
             !alongSameLine(pp->d, ll->d, tol)))
    return false;
  spec->axis_point = ll->q;
  spec->axis_dir = ll->d;
  spec->tip = pl->p;
  spec->approach = ll->u;
  spec->r_lo = pl->lo;
  spec->r_hi = pl->hi;
  spec->has_height = pp != nullptr;
  if (pp) {
    spec->plane_point = pp->q;
    spec->plane_normal = pp->d;
    spec->h_lo = pp->lo;
    spec->h_hi = pp->hi;
  }
  return true;
}

MatchResult matchMixed(MatchContext& ctx, const void* /*context*/) {
  if (ctx.set.revolve) return MatchResult::kNoMatch;  // only separable branches can be revolved
  const auto& ts = ctx.set.translational;
  if (ctx.set.rotational.empty() && ts.size() == 1 && ts[0].kind == FundamentalKind::kLineLine) {
    if (!ctx.branches.add<LineDistanceManifold>(ts[0])) return MatchResult::kOverflow;
    return MatchResult::kMatched;
  }
  RadialGraspSpec spec;
  if (radialGrasp(ctx.set, ctx.tol, &spec)) {
    for (double sigma : {1.0, -1.0}) {
      spec.sigma = sigma;
      if (!ctx.branches.add<RadialGraspManifold>(spec)) return MatchResult::kOverflow;
    }
    return MatchResult::kMatched;
  }
  return MatchResult::kNoMatch;
}

}  // namespace

void registerMixedManifolds(Registry& registry) {
  for (ManifoldInfo& m : mixedManifoldCatalogue()) registry.addManifold(std::move(m));
  registry.addMatcher({"mixed", &matchMixed});
}

}  // namespace relpos::manifolds
