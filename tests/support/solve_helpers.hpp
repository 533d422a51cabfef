#pragma once
// Shared test plumbing: a frozen built-in registry, solving, and sampling branches.
#include <random>
#include <string>

#include "relpos/core/registry.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::test {

const Registry& builtinRegistry();

// Random parameters of a branch within its bounds (unbounded lengths within ±window of 0).
Params sampleParams(const Manifold& m, std::mt19937_64& rng, double window = 3.0);

// Samples every branch of `s` (n poses each) and returns the largest input-constraint violation
// found, with a description of the worst pose for the failure message.
double worstSampledViolation(const Problem& p, const Solution& s, int n, std::uint64_t seed,
                             std::string* where = nullptr);

// Whether some branch of s contains X (its projection lands on X).
bool someBranchContains(const Solution& s, const Isometry3d& X, double tol = 1e-6);
// The largest DOF among the branches containing X (-1 when none does).
int dofOfBranchesContaining(const Solution& s, const Isometry3d& X, double tol = 1e-6);

// "rotation OneParallel ..., 1 DOF" lines for failure messages.
std::string describeBranches(const Solution& s);

// A pose as text that can be pasted into a test.
std::string poseText(const Isometry3d& X);

}  // namespace relpos::test
