#pragma once
// The numeric stage's turn (docs/spec.md §8): what the rules leave `unhandled` is handed to the
// registry's fallback, guarded, and its answer checked as the rules' is.
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::detail {

// `solution` is the rules' kUnhandled answer, `tol` the problem's tolerance. Calls
// registry.fallback() (which must be set) and keeps its answer when it answered and the answer
// holds up: each branch usable, exact or with a finite certificate, through the last check, the
// indices it lists in range. Otherwise the rules' answer stands, its message followed by what
// went wrong ("; the numeric stage 'NAME' (ORIGIN) threw: WHAT", "… answered …", or the
// stage's own reason).
void answerByFallback(const Problem& problem, const Registry& registry,
                      const SolverOptions& options, const Tolerance& tol, Solution& solution);

}  // namespace relpos::detail
