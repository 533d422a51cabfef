// Somani et al. (004) Table VII, first rows: parallel plane ranges on the same point (ranges.hpp).
#include <cmath>
#include <utility>

#include "family.hpp"
#include "ranges.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace range_pplane_pplane_family {
using namespace detail;

// A point-plane constraint with the overlap [lo, hi] on the first constraint's plane; a single
// value becomes an exact (folded) coincidence.
Fundamental planeRange(const Fundamental& a, Interval v, const Tolerance& tol) {
  if (v.hi - v.lo <= tol.length)
    return Fundamental::pointPlane(a.point_side, a.p, a.q, a.d, 0.5 * (v.lo + v.hi), a.sources);
  Fundamental f = Fundamental::pointPlane(a.point_side, a.p, a.q, a.d, 0.0, a.sources);
  f.lo = v.lo;
  f.hi = v.hi;
  return f;
}

void parallelSlabs(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out, const void* /*context*/) {
  if (bothExact(a, b) || !onePoint(a, b, tol)) return;
  if (!tol.parallelUnit(a.d.cross(b.d).norm())) return;  // crossing slabs: a parallelepiped
  // In a's reading t = (P − q_a)·n_a: b's values map by its orientation and plane offset.
  const double s = a.d.dot(b.d) > 0 ? 1.0 : -1.0;
  const double off = (b.q - a.q).dot(a.d);
  Interval ib{s * b.lo + off, s * b.hi + off};
  if (ib.lo > ib.hi) std::swap(ib.lo, ib.hi);
  // Slabs parallel only within the tolerance (beyond rounding) meet far away whatever their
  // offsets here: disjoint where the problem is centred is no conflict (as pplane+pplane).
  if (disjoint({a.lo, a.hi}, ib, tol) && Tolerance::tiltedBeyondRounding(a.d.cross(b.d).norm()))
    return out.defer();
  Interval both;
  if (intersect({a.lo, a.hi}, ib, tol, out, &both)) one(out, planeRange(a, both, tol));
}

constexpr RuleCaseRow kCases[] = {
    {kDisjoint, "disjoint", "Somani 004 Table VII, parallel plane ranges: disjoint ranges"},
    {kNested, "nested", "Somani 004 Table VII, parallel plane ranges: nested ranges"},
    {kOverlap, "overlap", "Somani 004 Table VII, parallel plane ranges: overlapping ranges"}};

}  // namespace range_pplane_pplane_family

constexpr RuleFamily families::range_pplane_pplane =
    family("range:pplane+pplane", "Somani 004 Table VII (PMF-style limit cases)",
           FundamentalKind::kPointPlane, FundamentalKind::kPointPlane,
           &range_pplane_pplane_family::parallelSlabs, range_pplane_pplane_family::kCases,
           /*handles_ranges=*/true);

}  // namespace relpos::rules
