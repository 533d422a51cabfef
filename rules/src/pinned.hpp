#pragma once
// What the pinned-point families (pp0_pp.cpp, pp0_pl.cpp, pp0_pplane.cpp) share: a pinned mobile
// point d(P_m, P_f) = 0 with one more translational constraint. With P pinned, T = P_f − R P_m, so
// any constraint on another point Q becomes a condition on the rotation of u = Q_m − P_m alone: an
// angle, two angles, or two pins. These generalise the p = 0 rows of PMF App. IV Tables I, II, V,
// VI, VIII and IX (derived from the geometry; the tables list special cases).
#include "rule_helpers.hpp"

namespace relpos::rules::detail {

inline bool pinned(const Fundamental& f, const Tolerance& tol) {
  return f.kind == FundamentalKind::kPointPoint && tol.zeroLength(f.value());
}

inline constexpr const char* kOutOfReach =
    "with one point pinned, the other constraint is out of reach";
inline constexpr const char* kSamePoint =
    "a pinned point that violates another constraint on the same point";

// The other constraint holds (drop it) or cannot hold: fires the family's Case::kImplied or
// Case::kIncompatible (every pinned-point family has both).
template <typename Case>
void impliedOrIncompatible(bool holds, RuleOutput& out, bool drop_first = false) {
  if (!holds) return out.fire(Case::kIncompatible).incompatible(kSamePoint);
  out.fire(Case::kImplied);
  if (drop_first)
    out.redundantFirst();
  else
    out.redundantSecond();
}

}  // namespace relpos::rules::detail
