#pragma once
// What the concentric range families share (range_pplane_pplane.cpp, range_pp_pp.cpp,
// range_pl_pl.cpp; Somani et al. (004) Table VII, first rows): two constraints on the same point
// whose loci are concentric — parallel planes, the same centre, the same axis — with at least one
// range. The allowed values form one interval each; their intersection decides: empty →
// incompatible, one inside the other → the wider is redundant, else a single range on the overlap.
#include <algorithm>

#include "rule_helpers.hpp"

namespace relpos::rules::detail {

// The three cases of each of the three families.
enum RangeCase { kDisjoint, kNested, kOverlap };

struct Interval {
  double lo, hi;
};

// Whether two intervals of the same quantity have nothing in common (beyond the tolerance).
inline bool disjoint(Interval a, Interval b, const Tolerance& tol) {
  return std::max(a.lo, b.lo) > std::min(a.hi, b.hi) + tol.length;
}

// Decides two intervals of the same quantity (the first constraint's), writing the overlap into
// `both`. Returns false when the rule made its decision without a replacement.
inline bool intersect(Interval a, Interval b, const Tolerance& tol, RuleOutput& out,
                      Interval* both) {
  both->lo = std::max(a.lo, b.lo);
  both->hi = std::min(a.hi, b.hi);
  if (disjoint(a, b, tol)) {
    out.fire(kDisjoint).incompatible(
        "two ranges on the same distance that do not overlap (Somani 004 Table VII)");
    return false;
  }
  if (both->hi < both->lo) both->hi = both->lo;
  auto inside = [&](Interval x, Interval y) {  // x ⊆ y
    return x.lo >= y.lo - tol.length && x.hi <= y.hi + tol.length;
  };
  if (inside(a, b)) {
    out.fire(kNested).redundantSecond();
    return false;
  }
  if (inside(b, a)) {
    out.fire(kNested).redundantFirst();
    return false;
  }
  out.fire(kOverlap);
  return true;
}

// The distance constraint a with the overlap v (exact when narrow).
inline Fundamental distanceRange(const Fundamental& a, Interval v, const Tolerance& tol) {
  Fundamental f = a;
  if (v.hi - v.lo <= tol.length) v.lo = v.hi = 0.5 * (v.lo + v.hi);
  f.lo = v.lo;
  f.hi = v.hi;
  return f;
}

inline bool bothExact(const Fundamental& a, const Fundamental& b) { return a.exact() && b.exact(); }

}  // namespace relpos::rules::detail
