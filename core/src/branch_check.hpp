#pragma once
// The checks every branch passes before it leaves the solver, whoever made it (a matcher or the
// numeric stage): solver.cpp defines them, fallback.cpp uses them too.
#include <string>

#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solution.hpp"

namespace relpos::detail {

// What would make a branch unusable without any exception to catch later ("" when nothing):
// no manifold, no type name, more parameters than a pose has room for, a parameter without a
// name. `call` names the method running, `type` the manifold's type name, should one throw.
std::string unusable(const ManifoldHolder& holder, const char*& type, const char*& call);

// How many tolerances a branch may break a constraint by at its reference parameters (rounding
// the rules' first-order allowances do not carry) before the last check calls it a breakdown.
inline constexpr double kBreakdownTolerances = 10.0;

// The last check (docs/spec.md §6.5): one pose of every branch of a solved answer against every
// input constraint; a breakdown makes the answer `unhandled` with the reason.
void checkBranches(const Problem& problem, const Registry& registry, const Tolerance& tol,
                   Solution& solution);

}  // namespace relpos::detail
