#pragma once
// Matcher steps that replace a constraint set by derived sets the solver combines and matches in
// turn (MatchResult::kDeferred): once the rotation is known (re-anchoring, PMF §V), or once it is
// known up to a turn about one fixed line (revolving, Somani 004 Fig. 2c).
#include "relpos/core/registry.hpp"
#include "relpos/manifolds/rotation_part.hpp"

namespace relpos::manifolds::detail {

constexpr int kMaxRotations = 8;

// Raw slots (FixedVector): a matcher creates one of these per constraint set it looks at, and
// default-constructing eight rotation parts each time was a tenth of a solve.
struct RotationAlternatives {
  FixedVector<RotationPart, kMaxRotations> parts;
  // err[k]: how far parts[k] may turn from the exact rotation (radians), when it was fixed from
  // derived vectors (Fundamental::err); 0 for vectors as given.
  double err[kMaxRotations];
  int size() const { return static_cast<int>(parts.size()); }
  void add(const RotationPart& r, double uncertainty = 0.0) {
    const int k = size();
    if (parts.push_back(r)) err[k] = uncertainty;
  }
};

// Every alternative is a fixed rotation: one derived set per rotation (and per side of each
// line-line distance), with every translational constraint re-anchored to the mobile origin.
MatchResult reanchorForEachRotation(MatchContext& ctx, const RotationAlternatives& rots);

// Every alternative spins about a fixed direction and every translational constraint is invariant
// under turning about one line along it: one derived set per alternative, its rotation fixed at
// φ = 0 and flagged `revolve`.
MatchResult revolveForEachRotation(MatchContext& ctx, const RotationAlternatives& rots);

}  // namespace relpos::manifolds::detail
