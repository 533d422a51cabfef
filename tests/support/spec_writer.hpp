#pragma once
// A Problem written back as a spec (docs/spec.md §1), so that a failing property case prints a file
// that `relpos solve` reproduces (as FCL prints the poses of a failing query). The property tests
// solve the parse of the very text they print (written()): writing a parsed problem again is not
// exact (a rotation's quaternion rounds), and near-degenerate verdicts flip on such last bits.
#include <string>

#include "relpos/core/problem.hpp"

namespace relpos::test {

// One line of JSON: the objects' poses (position + quaternion), their features, the constraints
// (angles in radians, every number with round-trip digits). Obstacles and meshes are left out:
// they play no part in solving.
std::string specJson(const Problem& p);

// specJson(p) and the problem relpos reads from it (ADD_FAILURE when that does not parse: a bug
// of the writer). Directions come back normalised and rotations re-orthonormalised, so the
// problem differs from p by rounding only, and is exactly what the text describes.
struct WrittenSpec {
  std::string text;
  Problem problem;
};
WrittenSpec written(const Problem& p);
inline Problem canonical(const Problem& p) { return written(p).problem; }

}  // namespace relpos::test
