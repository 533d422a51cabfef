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

// The same reading as a signed, smooth residual (measured minus value) for the exact scalar
// constraints a 0-DOF benchmark is made of: distance point-point, point-line (either role),
// point-plane (either role), an angle between lines and/or planes (false for any other kind).
// |*residual| == violation() wherever it returns true. For
// the random-start Newton of tests/support/reference_roots, which needs a sign to step on.
bool signedResidual(const InputConstraint& c, const Isometry3d& X_WF, const Isometry3d& X_WM,
                    double* residual);

}  // namespace relpos::test
