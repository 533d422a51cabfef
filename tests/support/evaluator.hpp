#pragma once
// An evaluator of input constraints written from docs/spec.md §1 alone, independent of the solver's
// decomposition and rules: it places both features and checks the "holds when" column.
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"

namespace relpos::test {

// Largest violation of constraint c at mobile pose X_WM (0 when it holds exactly). Lengths and
// angles (radians) are mixed: callers compare against a tolerance suited to both.
double violation(const InputConstraint& c, const Isometry3d& X_WF, const Isometry3d& X_WM);

// The largest violation over every constraint of the problem, and which constraint it was.
double worstViolation(const Problem& p, const Isometry3d& X_WM, int* which = nullptr);

}  // namespace relpos::test
