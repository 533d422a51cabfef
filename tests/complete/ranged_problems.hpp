#pragma once
// Random problems of 2-4 constraints of every kind built around a known pose, some of them
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

// 2-4 constraints of random kinds, each mobile feature fresh or (one time in three) the
// previous one's, each constraint a range one time in two (two-sided or one-sided either way),
// the mobile object starting at a random pose: the batch and fallback benchmarks' problems
// (bench/generate_random_specs.cpp, bench/fallback_bench.cpp). `grid`: axis-aligned integer
// geometry.
KnownProblem randomRangedProblem(Rng& rng, bool grid);

}  // namespace relpos::test
