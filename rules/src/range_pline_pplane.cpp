// A distance range cut by an exact constraint on the same point (Somani 004 Table VII, "range
// with exact constraint", derived by PMF's limit-case method): a thick cylinder cut by a plane
// parallel to its axis. With h the axis's distance from the plane and s the point's offset in the
// plane across the axis's trace, lo² ≤ h² + s² ≤ hi² leaves one strip |s| ≤ √(hi² − h²) when
// h ≥ lo, two strips √(lo² − h²) ≤ |s| ≤ √(hi² − h²) when h < lo, nothing when h > hi. (The
// gripper palm tangent to a can while the finger line keeps a distance range from its axis,
// 004 Fig. 2g.)
#include <algorithm>
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace range_pline_pplane_family {
using namespace detail;

enum Case { kDisjoint, kOneStrip, kTwoStrips };

// The point's offset along m from the plane through f, within [lo, hi] (exact when narrow).
Fundamental strip(const Fundamental& a, const Vector3d& f, const Vector3d& m, double lo, double hi,
                  const Tolerance& tol) {
  if (hi - lo <= tol.length)
    return Fundamental::pointPlane(a.point_side, a.p, f, m, 0.5 * (lo + hi), a.sources);
  Fundamental g = Fundamental::pointPlane(a.point_side, a.p, f, m, 0.0, a.sources);
  g.lo = lo;
  g.hi = hi;
  return g;
}

void cylinderCutByParallelPlane(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                                RuleOutput& out, const void* /*context*/) {
  // a: point-line range; b: exact point-plane on the same point, its plane parallel to the line.
  if (a.exact() || !b.exact() || !onePoint(a, b, tol)) return;
  if (std::abs(a.d.dot(b.d)) > tol.angle) return;
  const double signed_h = (b.q - a.q).dot(b.d);
  const double h = std::abs(signed_h);
  if (h > a.hi + tol.length) {
    // A plane parallel to the axis only within the tolerance (beyond rounding) crosses it far
    // away, where it cuts the thick cylinder: beyond the range here is no conflict.
    if (Tolerance::tiltedBeyondRounding(a.d.dot(b.d))) return out.defer();
    out.fire(kDisjoint).incompatible(
        "a plane parallel to a distance range's axis lies beyond the range (Somani 004 Table VII)");
    return;
  }
  const Vector3d foot = a.q + signed_h * b.d;  // the axis's trace in the plane
  const Vector3d m = accurateCross(a.d, b.d).normalized();
  const double outer = std::sqrt(std::max(0.0, a.hi * a.hi - h * h));
  if (h >= a.lo - tol.length) {
    out.fire(kOneStrip);
    two(out, b, strip(a, foot, m, -outer, outer, tol));
    return;
  }
  const double inner = std::sqrt(a.lo * a.lo - h * h);
  out.fire(kTwoStrips);
  two(out, b, strip(a, foot, m, inner, outer, tol));
  two(out, b, strip(a, foot, m, -outer, -inner, tol));
}

constexpr RuleCaseRow kCases[] = {
    {kDisjoint, "disjoint",
     "Somani 004 Table VII: a plane parallel to a thick cylinder's axis misses it"},
    {kOneStrip, "one-strip",
     "Somani 004 Table VII: a parallel plane cuts a thick cylinder in one strip"},
    {kTwoStrips, "two-strips",
     "Somani 004 Table VII: a parallel plane cuts a thick cylinder in two strips"}};

}  // namespace range_pline_pplane_family

constexpr RuleFamily families::range_pline_pplane =
    family("range:pline+pplane", "Somani 004 Table VII (PMF-style limit cases)",
           FundamentalKind::kPointLine, FundamentalKind::kPointPlane,
           &range_pline_pplane_family::cylinderCutByParallelPlane,
           range_pline_pplane_family::kCases, /*handles_ranges=*/true);

}  // namespace relpos::rules
