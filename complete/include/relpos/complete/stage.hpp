#pragma once
// The numeric stage's glue (issue 15, docs/spec.md §8): a problem the rules left unhandled,
// encoded (problem_encoding.hpp), solved by coefficient-parameter homotopy (fiber.hpp), and
// answered with one certified branch per proven-real root that meets every input constraint.
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos::complete {

// What proves each branch and the list (Branch::certified and Solution::complete hold the same;
// this adds the counts behind them).
struct StageReport {
  struct Certificate {
    double radius = 0.0;  // position, problem units
    double angle = 0.0;   // rotation (a line's direction), radians
  };
  std::vector<Certificate> certificates;  // per branch of the solution
  // Every isolated root of the family certified: no isolated pose is missing. (Not
  // Solution::complete: a positive-dimensional set of poses is not excluded.)
  bool complete = false;
  // Every real solution listed (Solution::complete): the interval proof over the bounded domain
  // held for every subproblem (docs/spec.md §8.3), in proof_boxes boxes.
  bool real_complete = false;
  int proof_boxes = 0;
  std::string real_doubt;  // why not, when not
  int root_count = 0;     // the family's
  int roots_found = 0;    // distinct certified roots
  int real_roots = 0;     // proven real
  std::string signature;  // the family's
};

// How the stage may spend its time (added for issue 15's CI budget and for callers in a control
// loop): computing a start system the repository does not store takes seconds to minutes, once
// per constraint signature and process.
struct StageOptions {
  // false: a problem whose family has no stored start system is declined (solveComplete returns
  // false, saying so) instead of computing one.
  bool compute_start_systems = true;
  // The interval proof that no real solution is missing (docs/spec.md §8.3): how many boxes it
  // may examine per subproblem before giving up (then `complete` stays false; 0: not tried).
  // Lines: tried on every problem (two degrees of freedom to search: about 3,000 boxes, 20 ms, for
  // the four spheres). Poses: tried only when no real pose was found, to prove the problem
  // inconsistent; at six degrees of freedom the search rarely ends within a budget worth
  // spending while poses exist (measured: 2 of 30 random 6-6, octahedral and mixed problems
  // within 20,000 boxes, 15 µs each).
  int line_proof_boxes = 20000;
  int pose_proof_boxes = 4000;
  // Threads tracking the paths of a family with at least 16 roots (0: two where the machine has
  // two cores or more). The answer is the same for every value; the 6-6 platform's 40 paths take
  // 5.8 ms on one thread and 3.3 ms on two.
  int threads = 0;
  // Sets of poses (solveSets): the start poses per alternative of the constraints (the mobile
  // object's own, then seeded random ones) and the most charts (branches) an answer holds,
  // shared among the alternatives (each at least one: an "either" orientation's other side is
  // another piece of the set). Each chart costs about 100 µs to find and prove (the random
  // 2-4-constraint problems of bench/fallback_bench.cpp: median 120 µs with one, 200 µs with
  // two, 420 µs with four).
  int set_starts = 12;
  int max_charts = 2;
  // When no start leads to a pose: the boxes each attempt of the interval proof that none exists
  // may examine (the whole problem's, then each with one constraint dropped, for the conflict).
  int exclusion_boxes = 6000;
};

// Applies when every constraint is a built-in type with an exact value that the encodings take
// and they give as many equations as unknowns (6 for a pose; 4 for a line, when every mobile
// feature lies on one line). Then, when some certified real root meets every constraint: solved
// with those branches (0-DOF poses, or a line's 2-DOF spin and slide), each exact = false with
// its certificate (Branch::certified), solution.complete false (a positive-dimensional set of
// poses is not excluded; report->complete says whether every isolated one was found), and true.
// Otherwise false, with the reason in solution.message and nothing else of the solution changed
// (never inconsistent: no real isolated root does not exclude a positive-dimensional set).
bool solveComplete(const Problem& problem, const Registry& registry, const Tolerance& tol,
                   Solution& solution, StageReport* report = nullptr,
                   const StageOptions& options = StageOptions());

// What solveComplete does not take: any built-in constraints, exact or ranges, whose poses form
// sets (or isolated poses) found by descent from StageOptions::set_starts starts. Each pose found
// where the equations are independent and every range holds strictly becomes a certified chart
// (docs/spec.md §8.7): a branch of the set's local dimension, exact = false, its certificate the
// chart's slice. solved with the charts found, never complete (a component may be missed, or
// covered in part); false with the reason when none is found (never inconsistent).
bool solveSets(const Problem& problem, const Registry& registry, const Tolerance& tol,
               Solution& solution, const StageOptions& options = StageOptions());

}  // namespace relpos::complete
