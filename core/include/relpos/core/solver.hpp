#pragma once
// solve(problem, registry, options, workspace, solution): decompose -> combine -> synthesise
// (docs/architecture.md). Never throws and never reads files on a valid problem; the status says
// what happened. Reusing the Workspace and the Solution makes repeated solves allocation-free.
#include <random>
#include <string>
#include <vector>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

struct SolverOptions {
  int max_branches = 64;     // more alternatives than this -> unhandled
  int max_rule_steps = 256;  // rewrite steps per constraint set before giving up (unhandled)
  // Every rule condition ("parallel", "d_a = d_b", "on the line") is decided within these:
  // lengths relative to the problem's size (the diagonal of its constrained features' box, or a
  // longer length value; never below the rounding of its largest coordinate), angles in radians
  // (docs/spec.md §6, "Tolerances and numerical soundness"). Loosen them for data with few
  // significant digits (e.g. 1e-6 for CAD exports).
  double length_tolerance = 1e-9;
  double angle_tolerance = 1e-9;
  bool isValid(std::string* why) const;
};

class Workspace {
 public:
  Workspace();
  // Internal buffers (public for the solver's translation units; not part of the API contract).
  std::vector<ConstraintSet> pending;  // constraint sets still to combine (the branch stack)
  RuleOutput rule_out;
  std::vector<std::string> problems;  // value checks of constraints built in code
  // The answer to the same problem with every tolerance 10 times wider, which an `inconsistent`
  // one is held against (docs/spec.md §6.4): kept here so that solving again allocates nothing.
  Solution widened;
};

void solve(const Problem& problem, const Registry& registry, const SolverOptions& options,
           Workspace& workspace, Solution& solution);

// Combines and synthesises a set of fundamental constraints directly (no decomposition): for rule
// and plugin test kits, which check what a rule's output set admits.
void solveConstraintSet(const ConstraintSet& set, const Tolerance& tol, const Registry& registry,
                        const SolverOptions& options, Workspace& workspace, Solution& solution);

// Convenience: a fresh workspace and solution.
Solution solve(const Problem& problem, const Registry& registry,
               const SolverOptions& options = SolverOptions());

// Fills `nearest` parameters for every branch: see nearestParams.
struct NearestPose {
  Params parameters{};
  Isometry3d pose = Isometry3d::Identity();
  double distance = 0.0;
  bool global = false;  // proven the nearest of the whole branch (nearestIsGlobal)
};
NearestPose nearestOnBranch(const Branch& b, const Isometry3d& X_WM_initial);

// Parameters drawn uniformly within the manifold's bounds; an unbounded one within ±window of
// centre's (docs/spec.md §2 `samples`: centre = the nearest pose's parameters), the centre taken
// within the bounds first (a half-unbounded parameter's window then never leaves them).
Params sampleParameters(const Manifold& m, const Params& centre, double window,
                        std::mt19937_64& rng);

}  // namespace relpos
