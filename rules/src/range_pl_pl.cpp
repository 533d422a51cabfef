// Somani et al. (004) Table VII, first rows: coaxial distance ranges on the same point
// (ranges.hpp).
#include <cmath>
#include <utility>

#include "family.hpp"
#include "ranges.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace range_pl_pl_family {
using namespace detail;

void coaxialCylinders(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                      RuleOutput& out, const void* /*context*/) {
  if (bothExact(a, b) || !onePoint(a, b, tol)) return;
  const Vector3d w = b.q - a.q;
  if (!tol.parallelUnit(a.d.cross(b.d).norm()) || (w - w.dot(a.d) * a.d).norm() > tol.length)
    return;
  // Axes parallel only within the tolerance (beyond rounding) drift apart along their length,
  // where distances to them differ by up to that drift: disjoint ranges here are no conflict.
  if (disjoint({a.lo, a.hi}, {b.lo, b.hi}, tol) &&
      Tolerance::tiltedBeyondRounding(a.d.cross(b.d).norm()))
    return out.defer();
  Interval both;
  if (intersect({a.lo, a.hi}, {b.lo, b.hi}, tol, out, &both)) one(out, distanceRange(a, both, tol));
}

constexpr RuleCaseRow kCases[] = {
    {kDisjoint, "disjoint", "Somani 004 Table VII, coaxial distance ranges: disjoint ranges"},
    {kNested, "nested", "Somani 004 Table VII, coaxial distance ranges: nested ranges"},
    {kOverlap, "overlap", "Somani 004 Table VII, coaxial distance ranges: overlapping ranges"}};

}  // namespace range_pl_pl_family

constexpr RuleFamily families::range_pl_pl = family(
    "range:pl+pl", "Somani 004 Table VII", FundamentalKind::kPointLine, FundamentalKind::kPointLine,
    &range_pl_pl_family::coaxialCylinders, range_pl_pl_family::kCases, /*handles_ranges=*/true);

}  // namespace relpos::rules
