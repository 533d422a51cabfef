#pragma once
// The benchmark problems of the complete solvers (data/complete, written by
// scripts/make_complete_specs.py) and what the literature says of them, shared by the tests.
#include <ostream>
#include <string>
#include <vector>

#include "reference_roots.hpp"
#include "relpos/core/problem.hpp"

namespace relpos::test {

struct BenchmarkProblem {
  const char* file;        // in data/complete
  bool line_quotient;      // the mobile object is one line (spin and slide free)
  int literature_count;    // real solutions the literature states; -1 when it gives none
  const char* literature;  // where that count comes from
};

const std::vector<BenchmarkProblem>& benchmarkProblems();
// The one whose file is `file` (std::runtime_error when none is).
const BenchmarkProblem& problemNamed(const std::string& file);

// GoogleTest prints a parameter with this (its file name) instead of its bytes.
inline void PrintTo(const BenchmarkProblem& b, std::ostream* os) { *os << b.file; }

Problem loadComplete(const std::string& file);

// The reference set for a benchmark problem, computed once per process (thousands of solves).
const ReferenceRoots& benchmarkReference(const BenchmarkProblem& b);

}  // namespace relpos::test
