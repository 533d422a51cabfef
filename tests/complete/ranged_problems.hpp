#pragma once
// Random problems of 2-3 constraints of every kind built around a known pose, some of them
// ranges (two-sided or one-sided either way): what the numeric stage's charts and its proofs of
// inconsistency are tested on (chart_stage_test.cpp, conflict_proof_test.cpp).
#include "random_problems.hpp"

namespace relpos::test {

// Turns constraint c (of a kind with a value) into a range about its value: two-sided
// (sides 0), at least (1) or at most (2), within what the spec accepts.
void widenToRange(InputConstraint& c, const SingleKind& kind, Rng& rng, int sides);

// The index-th problem (its kinds and ranges vary with the index), the mobile object starting
// at the known pose.
KnownProblem rangedProblem(Rng& rng, int index);

}  // namespace relpos::test
