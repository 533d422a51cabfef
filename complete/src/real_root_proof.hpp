#pragma once
// Whether every real solution of an encoded problem is among the certified real roots found
// (docs/spec.md §8.3, `complete`): counting isolated roots cannot say so — a special member may
// have a curve of real poses that no path reaches — so the real system is searched over a
// bounded domain by interval branch and prune (exclusion.hpp). For a pose the chart c·e = 1 is
// replaced by e·e = 1 (every pose is then ±(e, g) with e₀ ≥ 0 covering it) and the translation is
// bounded by the constraints that bound it; for a line (w, q) the direction is a unit vector and
// the foot is bounded by the point distances and plane offsets.
#include <string>
#include <vector>

#include "exclusion.hpp"
#include "relpos/complete/fiber.hpp"
#include "relpos/complete/problem_encoding.hpp"

namespace relpos::complete::detail {

// roots: the fiber's certified roots (the real ones are the known real solutions; a root not
// proven real counts as unknown, so it can only make the proof fail).
ExclusionResult proveRootsKnown(const PoseEncoding& enc, const std::vector<CertifiedRoot>& roots,
                                    const ExclusionOptions& options = ExclusionOptions());
ExclusionResult proveRootsKnown(const LineEncoding& enc, const std::vector<CertifiedRoot>& roots,
                                    const ExclusionOptions& options = ExclusionOptions());

}  // namespace relpos::complete::detail
