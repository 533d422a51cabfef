#pragma once
// relpos's branches against a reference solution set (tests/support/reference_roots): the checks
// of the benchmark problems, as a list of failures so that the checks themselves can be tested
// on solutions made to be wrong (reference_comparison_test.cpp).
#include <string>
#include <vector>

#include "reference_roots.hpp"
#include "relpos/core/solution.hpp"

namespace relpos::test {

// Empty when: as many branches as reference roots (lines: as many distinct undirected lines),
// every sampled branch pose holds every constraint, every reference root (lines: in both
// directions of the mobile line) lies on a branch, branches have 0 DOF (lines: 2) and no two are
// the same pose (lines: the same directed line).
std::vector<std::string> compareWithReference(const Problem& p, const Solution& s,
                                              const ReferenceRoots& ref, bool line_quotient);

// The pose a branch stands for: at its reference parameters.
Isometry3d branchPose(const Branch& b);

// A half turn about an axis across the mobile line through its point: X·flip is X with the
// mobile line reversed on the same world line.
Isometry3d lineFlip(const Problem& p);

}  // namespace relpos::test
