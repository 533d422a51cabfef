#pragma once
// A Problem written back as a spec (SPEC.md §1), so that a failing property case prints a file
// that `relpos solve` reproduces (as FCL prints the poses of a failing query). The property tests
// solve the spec's own parse (canonical()), so the printed text is exactly the problem that failed.
#include <string>

#include "relpos/core/problem.hpp"

namespace relpos::test {

// One line of JSON: the objects' poses (position + quaternion), their features, the constraints
// (angles in radians, every number with round-trip digits). Obstacles and meshes are left out:
// they play no part in solving.
std::string specJson(const Problem& p);

// The problem as relpos reads specJson(p) back (ADD_FAILURE when that does not parse: a bug of
// the writer). Directions come back normalised and rotations re-orthonormalised, so the result
// differs from p by rounding only.
Problem canonical(const Problem& p);

}  // namespace relpos::test
