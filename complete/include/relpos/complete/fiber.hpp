#pragma once
// Every isolated root of one real member of a Family, each certified (issue 15, docs/spec.md §8):
// coefficient-parameter homotopy from the family's start system (start_system.hpp), every
// endpoint proven by Krawczyk's test in Boost.Interval, boxes checked pairwise disjoint. The
// count of distinct certified roots equal to the family's root count proves the list complete.
// Deterministic: the same family, target and options give the same roots in the same order, on
// every run and thread count.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete {

// The roots of a generic complex member (the start of every homotopy in its family).
struct StartSystem {
  std::vector<Complex> params;          // parameterCount()
  std::vector<Eigen::VectorXcd> roots;  // all of its isolated roots (the family's root count)
  // How the count was checked (added for issue 15's engine): "monodromy+total-degree" (the
  // Bézout homotopy's roots added: total_degree_added of them were new to monodromy) or, when
  // the Bézout number is above 4096, "monodromy+second-monodromy" (a monodromy run from an
  // independent member, its roots carried over and added). Neither is a proof. The generator of
  // the stored start systems appends "+trace" when the trace test passed (trace_test.hpp: every
  // root of the family's main component is held, conditional on correct path tracking).
  std::string check;
  int monodromy_loops = 0;
  int total_degree_paths = 0;  // 0: the Bézout number was above the limit, not run
  int total_degree_added = 0;
  int second_monodromy_roots = 0;  // the second run's own count, when it ran
  int second_monodromy_added = 0;
  int trace_witness_points = 0;  // the trace test's witness set (0: not run or not passed)
  // The work of computing it (added for issue 18's step budget, docs/spec.md §8.5): the
  // predictor-corrector steps of its paths, and the Krawczyk tests of the roots found (each
  // one's certificate, and those that told it from the known ones); a budget of max_steps holds
  // steps + root_tests. 0 for a stored one.
  std::int64_t steps = 0;
  std::int64_t root_tests = 0;
  // Read from the start systems stored in the repository (data/start_systems, compiled in)
  // rather than computed in this process; check says how the generator checked it (added for
  // issue 15's stored start systems).
  bool stored = false;
};

// The start system of f's signature: the one stored in the repository for it when there is one
// (data/start_systems, compiled into the library, checked against f on first use), else computed
// on first use (monodromy from f.seedMember, seeded by the signature, so the same on every run);
// kept for the process; thread-safe.
const StartSystem& startSystem(const Family& f);
// The same, or nullptr when none is stored and `compute` is false (added for issue 15's stage
// options: a solve that must not spend seconds computing a start system), or when computing
// it would take more tracking steps than a solve may (detail::kSolvingStepBudget, issue 16: a
// family of thousands of roots or crawling paths; startSystem computes it whatever it costs).
const StartSystem* findStartSystem(const Family& f, bool compute);
// Loads every stored start system now (each checked against its family, as on first use), so
// that the first solve of a family pays no loading: for a control loop's start-up, and for
// tools that time each solve. Returns how many were loaded.
int preloadStoredStartSystems();

struct CertifiedRoot {
  Eigen::VectorXcd x;   // the root's approximation (box centre)
  double radius = 0.0;  // the box x ± radius (every real and imaginary part) holds exactly one root
  bool real = false;    // proven real: a real box (imaginary parts 0) passed the test
};

struct FiberOptions {
  std::uint64_t seed = 1;  // of the random γ of each tracking attempt
  int attempts = 3;        // tracking attempts (a new γ each) before giving up on a missing root
  // Threads tracking the paths of one call (added for issue 15's engine): 1 runs in the caller's
  // thread; the answer is the same for every value.
  int threads = 1;
  // Compute the start system when none is stored (seconds to minutes, once per signature and
  // process); false: a family without a stored one gets no roots and start_system_missing.
  bool compute_start_system = true;
};

struct FiberResult {
  std::vector<CertifiedRoot> roots;  // distinct (disjoint boxes), sorted deterministically
  int root_count = 0;                // the family's root count (paths tracked per attempt)
  bool complete = false;             // roots.size() == root_count: no isolated root is missing
  int attempts = 0;                  // attempts used
  bool start_system_missing = false;  // none stored and options.compute_start_system false
};

// target: the real member's parameters (parameterCount()).
FiberResult solveFiber(const Family& f, const std::vector<double>& target,
                       const FiberOptions& options = FiberOptions());

}  // namespace relpos::complete
