// Somani et al. (004) Table VII, first rows: concentric distance ranges on the same point
// (ranges.hpp).
#include <cmath>
#include <utility>

#include "family.hpp"
#include "ranges.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace range_pp_pp_family {
using namespace detail;

void concentricSpheres(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                       RuleOutput& out, const void* /*context*/) {
  if (bothExact(a, b) || (a.p - b.p).norm() > tol.length || (a.q - b.q).norm() > tol.length) return;
  Interval both;
  if (intersect({a.lo, a.hi}, {b.lo, b.hi}, tol, out, &both)) one(out, distanceRange(a, both, tol));
}

constexpr RuleCaseRow kCases[] = {
    {kDisjoint, "disjoint", "Somani 004 Table VII, concentric distance ranges: disjoint ranges"},
    {kNested, "nested", "Somani 004 Table VII, concentric distance ranges: nested ranges"},
    {kOverlap, "overlap", "Somani 004 Table VII, concentric distance ranges: overlapping ranges"}};

}  // namespace range_pp_pp_family

constexpr RuleFamily families::range_pp_pp =
    family("range:pp+pp", "Somani 004 Table VII", FundamentalKind::kPointPoint,
           FundamentalKind::kPointPoint, &range_pp_pp_family::concentricSpheres,
           range_pp_pp_family::kCases, /*handles_ranges=*/true);

}  // namespace relpos::rules
