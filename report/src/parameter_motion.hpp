#pragma once
// The motion each parameter of a branch makes (relpos/io/report.hpp ParameterMotion), computed
// from the branch's pose function alone, so that it holds for every manifold, a plugin's too.
#include <array>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/io/report.hpp"

namespace relpos::detail {

// The motion of every parameter of `branch` at parameters `at` (its nearest pose's), by central
// differences of pose(θ) within the bounds, and the ranged input constraint each range parameter
// spans. Runs the branch's code: a throw beside `at` makes that motion unknown (the stage that
// needs those poses reports it); one at `at` itself is let through.
void parameterMotions(const Problem& problem, const Branch& branch, const Params& at,
                      std::array<ParameterMotion, kMaxDof>& out);

}  // namespace relpos::detail
