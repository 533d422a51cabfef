#pragma once
// Equations the others imply (docs/spec.md §8.7): constraints that share a mobile feature often
// say some things twice — a point on a point and on a line through it, two parallelisms of one
// axis — and their equations are then dependent everywhere on the set, so no pose of it is a
// regular point of them all and no chart can be proven. Linear equations on one mobile point
// (plane offsets: d·x = b, x = R p + t) or on one mobile direction (cosines: d·(R u) = b) are
// reduced like a linear system: an equation whose normal lies in the span of the earlier ones
// (to 1e-13) is implied by them up to its value's mismatch, and dropped when that is within the
// tolerance. Its violation anywhere on the others' set is then at most the mismatch plus the
// normal's residual times |x| (a cosine: times 1), which each chart checks for its own reach.
#include <vector>

#include "pose_conditions.hpp"

namespace relpos::complete::detail {

// A normal within this of the earlier ones' span is in it (dependent everywhere, not by a
// coincidence of the pose): far below any tolerance, far above the rounding of normalised data.
constexpr double kInSpan = 1e-13;

// A plane offset or a cosine: linear in the mobile point x or direction R u.
inline bool linear(const Condition& c) {
  return c.kind == ConditionKind::kPointPlane || c.kind == ConditionKind::kCosine;
}

struct ImpliedEquation {
  Condition condition;
  double mismatch = 0.0;  // |b' − b|: the value the earlier equations give it, against its own
  double residual = 0.0;  // |r|: its normal's distance from their span
  double weight = 0.0;    // Σ|α|: how much the earlier equations' own errors move it
};

// Drops from system->equations those the earlier ones imply within the tolerances (normalised
// length; radians), into `dropped`.
void dropImpliedEquations(ConditionSystem* system, double length_tolerance, double angle_tolerance,
                          std::vector<ImpliedEquation>* dropped);

// The largest violation of a dropped equation anywhere within `reach` of the origin (normalised)
// where the earlier equations hold to `earlier` (0: exactly; a chart that itself dropped some of
// them holds those only to what it proved): what a chart reaching that far must keep within the
// tolerance.
double impliedViolation(const ImpliedEquation& e, double reach, double earlier);

}  // namespace relpos::complete::detail
