#pragma once
// The conditions as the proof of inconsistency reads them (set_exclusion.hpp, docs/spec.md
// §8.8): widened by the tolerances, with what pairs of them imply for the rotation alone, and an
// angle-only system's direction turned onto z.
#include <vector>

#include "pose_conditions.hpp"
#include "relpos/core/fundamental.hpp"

namespace relpos::complete::detail {

// Condition c with its range widened by the tolerances tl (normalised length) and ta (radians),
// into `out`: a pose meeting the constraint within them meets it (an exact skew distance becomes
// its two sides; a side that bounds nothing once widened is dropped).
void widen(const Condition& c, double tl, double ta, std::vector<Condition>* out);

// Adds the reach a point on a point implies (its three axis offsets' diagonal).
void addImpliedReaches(std::vector<Condition>* cs);

// When every condition is an angle of one mobile direction u (or −u): u replaced by z (−z), and
// true — the rotation search may then drop the spin about z.
bool turnedOntoZ(std::vector<Condition>* cs);

// The conditions, and after them what each pair implies for the rotation alone (two offsets
// along one normal, two reaches, a reach and an offset); `sources`: each one's constraints.
void withRotationParts(const std::vector<Condition>& cs, std::vector<Condition>* out,
                       std::vector<SourceMask>* sources);

}  // namespace relpos::complete::detail
