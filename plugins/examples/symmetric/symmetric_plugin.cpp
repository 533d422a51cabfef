// Example plugin (a): a constraint type with its decomposition, and a combination rule.
//
// `symmetric` (fixed plane, mobile line): the line crosses the plane at right angles at its
// point, so the points `point ± s·direction` are mirror images in the plane for every s — the two
// fingertips of a parallel gripper centred on an object's mid-plane. It decomposes into the point
// on the plane and the line along the normal, either way round (PMF §III fundamentals).
//
// `shell-cut:pp+pplane`: a point kept within [lo, hi] of a centre C (a spherical shell) and on a
// plane at signed distance h from C lies in the plane's annulus about the foot of C, radii
// √(lo² − h²) … √(hi² − h²) (a disc when |h| ≥ lo, nothing when |h| > hi). Derived like Somani
// 004 Table VII; the built-in rules leave this pair alone.
#include <algorithm>
#include <cmath>

#include "relpos/core/plugin_api.hpp"

namespace symmetric_plugin {
using namespace relpos;

void decomposeSymmetric(const InputConstraint& c, const Feature& plane_W, SourceMask s,
                        Decomposition& out, const void* /*context*/) {
  const Feature& line = c.mobile;
  const Fundamental on_plane =
      Fundamental::pointPlane(Side::kMobile, line.point, plane_W.point, plane_W.direction, 0.0, s);
  for (double sign : {1.0, -1.0}) {
    auto& alt = out.addAlternative();
    alt.push_back(on_plane);
    alt.push_back(Fundamental::angle(line.direction, sign * plane_W.direction, 0.0, s));
  }
}

enum Case { kDisjoint, kDisc, kAnnulus };

void shellCutByPlane(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                     RuleOutput& out, const void* /*context*/) {
  // a: point-point range (point mobile); b: exact point-plane on the same mobile point.
  if (a.exact() || !b.exact() || b.point_side != Side::kMobile || (a.p - b.p).norm() > tol.length)
    return;
  const double h = (a.q - b.q).dot(b.d);  // the centre's signed distance from the plane
  if (std::abs(h) > a.hi + tol.length) {
    out.fire(kDisjoint).incompatible("a plane beyond a point-point distance range");
    return;
  }
  const Vector3d foot = a.q - h * b.d;
  Fundamental ring = Fundamental::pointLine(Side::kMobile, a.p, foot, b.d, 0.0, a.sources);
  ring.hi = std::sqrt(std::max(0.0, a.hi * a.hi - h * h));
  ring.lo = std::abs(h) >= a.lo ? 0.0 : std::sqrt(a.lo * a.lo - h * h);
  if (ring.hi - ring.lo <= tol.length) ring.lo = ring.hi;  // a circle
  out.fire(ring.lo == 0.0 ? kDisc : kAnnulus);
  auto& alt = out.addAlternative();
  alt.push_back(b);
  alt.push_back(ring);
}

void registerAll(Registry& registry) {
  ConstraintType t;
  t.name = "symmetric";
  t.description =
      "plane(f)-line(m): the line crosses the plane at right angles at its point (mirror-image "
      "points on it, e.g. two fingertips centred on a mid-plane)";
  t.accepts = {{FeatureKind::kPlane, FeatureKind::kLine}};
  t.decompose = &decomposeSymmetric;
  registry.addConstraintType(t);

  RuleInfo r;
  r.name = "shell-cut:pp+pplane";
  r.citation = "symmetric plugin, after Somani 004 Table VII";
  r.first = FundamentalKind::kPointPoint;
  r.second = FundamentalKind::kPointPlane;
  r.fn = &shellCutByPlane;
  r.handles_ranges = true;
  r.cases = {{"shell-cut:pp+pplane/disjoint", "a plane beyond the shell: no point"},
             {"shell-cut:pp+pplane/disc", "a plane within the inner radius: a disc"},
             {"shell-cut:pp+pplane/annulus", "a plane through the shell's wall: an annulus"}};
  registry.addRule(r);
}

}  // namespace symmetric_plugin

RELPOS_PLUGIN(symmetric_plugin::registerAll)
