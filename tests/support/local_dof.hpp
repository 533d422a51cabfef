#pragma once
// The dimension of the solution set at a pose, measured independently of the solver: the rank of
// the Jacobian of smooth residuals of every input constraint (written from docs/spec.md §1) with
// respect to a small rigid motion of the mobile object. At a generic point of a smooth branch,
// 6 − rank is the branch's DOF.
#include "relpos/core/problem.hpp"

namespace relpos::test {

int localDof(const Problem& p, const Isometry3d& X_WM);

}  // namespace relpos::test
