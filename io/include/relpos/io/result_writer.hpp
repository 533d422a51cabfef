#pragma once
// Writing results (SPEC.md §2).
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

struct ResultOptions {
  int samples = 0;      // poses per branch (--samples)
  double window = 1.0;  // half-width for unbounded length parameters (--window)
  std::uint64_t seed = 0;
};

// A pose as SPEC.md §2 writes it: parameters, position, orientation (x, y, z, w with w ≥ 0).
nlohmann::ordered_json poseToJson(const Isometry3d& X, const Params& theta, int dof);

// The result document of SPEC.md §2 (nearest pose per branch, best, samples, etc.) as one line
// of compact JSON, into `out` (reused: a batch keeps one per thread).
void writeResultLine(const Problem& problem, const Solution& solution, const ResultOptions& options,
                     std::string& out);

// The same document as a JSON tree (to add fields to, or to print indented).
nlohmann::ordered_json resultToJson(const Problem& problem, const Solution& solution,
                                    const ResultOptions& options);

}  // namespace relpos
