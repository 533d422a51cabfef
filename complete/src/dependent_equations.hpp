#pragma once
// Equations dependent where they hold (docs/spec.md §8.7): beyond the linear ones
// implied_equations.hpp drops, constraints can say one thing twice through different features — a
// line through a fixed point and at its distance from a fixed parallel, a pin in a groove on the
// table a face rests on — and then no pose of the set is a regular point of all the equations.
// Where the dependent ones are constants on the set of the others, a chart of the others is a
// chart of the set.
#include <vector>

#include "pose_conditions.hpp"

namespace relpos::complete::detail {

// Where the equations are dependent at a pose (R0, t0): the ones independent there (greedily,
// in order) are kept; each other one must be a constant on any connected piece of the kept
// ones' set through the pose. With six kept, that piece is the pose alone (an overdetermined
// system's isolated pose). Otherwise it is so by what the kept ones hold constant there — a
// direction pinned by two angle rows (finitely many directions meet them) or every direction
// when the angles pin the rotation (rank 3 in its coordinates), a mobile point's coordinates
// along its plane rows' normals (every point's along every normal with the rotation pinned) —
// and what it reads of them: an angle a pinned direction, a plane offset a held normal, a
// distance to a point a point held whole, to a fixed line the point held across it, a fixed
// point's distance to a mobile line (plane) its pinned direction and the point held across
// (along) it, a skew distance of a mobile line its pinned direction and the point held across
// it; and the further holds of docs/spec.md §8.7 (a point along or across a direction pinned
// by right angles, a skew distance across one). Which dependent ones are dropped: the greedy
// choice, else the first other choice that works. Returns the system without those (`dropped`,
// in the system's frame; a skew distance constant only where its lines are not parallel adds
// an inequality keeping them apart); false when some dependent equation is not such a
// constant, or none is dependent. The caller proves the dropped ones hold at the exact pose of
// the kept ones (chart.hpp, holdAtExactBase): then on the whole piece.
bool reduceDependent(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0,
                     ConditionSystem* reduced, std::vector<Condition>* dropped);

// The input constraints (their bits) whose equations are dependent at pose (R0, t0): those with
// weight in a combination of the equations' gradients that vanishes there (a singular value
// under 1e-6 of the largest) — what a message names when no chart could be proven.
SourceMask dependentSources(const ConditionSystem& system, const Matrix3d& R0,
                            const Vector3d& t0);

}  // namespace relpos::complete::detail
