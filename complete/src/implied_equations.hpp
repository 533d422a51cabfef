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

// Where the equations are dependent at a pose (R0, t0): the ones independent there (greedily,
// in order) are kept; each other one must be a constant on any connected piece of the kept
// ones' set through the pose, by what the kept ones hold constant there — a direction pinned by
// two angle rows (finitely many directions meet them) or every direction when the angles pin
// the rotation (rank 3 in its coordinates), a mobile point's coordinates along its plane rows'
// normals (every point's along every normal with the rotation pinned) — and what it reads of
// them: an angle a pinned direction, a plane offset a held normal, a distance to a point a
// point held whole, to a fixed line the point held across it, a fixed point's distance to a
// mobile line (plane) its pinned direction and the point held across (along) it, a skew
// distance of a mobile line its pinned direction and the point held across it. Returns the
// system without those (`dropped`, in the system's frame); false when some dependent equation
// is not such a constant, or none is dependent. The caller proves the dropped ones hold at the
// exact pose of the kept ones (chart.hpp, holdAtExactBase): then on the whole piece.
bool reduceDependent(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0,
                     ConditionSystem* reduced, std::vector<Condition>* dropped);

}  // namespace relpos::complete::detail
