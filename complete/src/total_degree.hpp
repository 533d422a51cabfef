#pragma once
// The total-degree homotopy H = (1 − s) γ G + s F, G_k = x_k^{d_k} − 1 (d_k: equation k's degree):
// all Bézout-many paths from the roots of unity, with the γ trick. Used once per signature, as
// an independent cross-check of the start system's root count found by monodromy.
#include <cstdint>
#include <vector>

#include "polynomial_eval.hpp"

namespace relpos::complete::detail {

// The product of the equations' degrees (saturating at 2^62).
std::uint64_t bezoutNumber(const CompiledShape& shape);

// Every finite endpoint (polished, not yet deduplicated or certified) of the total-degree
// homotopy to the member of `shape` with coefficients `coefficients`.
// `steps_left` (when set): the predictor-corrector steps the paths may take; each path's are
// taken from it, and past 0 the tracking stops (the endpoints then incomplete).
std::vector<CVec> totalDegreeEndpoints(const SystemShape& shape, const Complex* coefficients,
                                       std::uint64_t seed, std::int64_t* steps_left = nullptr);

}  // namespace relpos::complete::detail
