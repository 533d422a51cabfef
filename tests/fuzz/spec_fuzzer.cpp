// libFuzzer target (issue 13): any bytes through the spec reader, the solver and the result
// writer, the way `relpos batch` handles a line — parseSpec, solve, writeResultLine with samples
// and a fixed seed — and what was written read back and checked (result_checks.hpp). A broken
// invariant aborts, so that libFuzzer keeps the input (crash-<sha1> in its working folder).
// Build: RELPOS_FUZZ=ON with clang (scripts/run_fuzz.sh).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "known_failures.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/complete/fiber.hpp"
#include "relpos/complete/register.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"
#include "result_checks.hpp"

namespace {

constexpr int kSamples = 4;
constexpr std::uint64_t kSeed = 1;

[[noreturn]] void fail(const relpos::fuzz::Findings& findings) {
  for (const auto& f : findings)
    std::fprintf(stderr, "relpos_spec_fuzzer: %s: %s\n", f.kind.c_str(), f.detail.c_str());
  std::fflush(stderr);
  std::abort();
}

// The built-ins with the numeric stage limited to the stored start systems: a mutated 0-DOF spec
// of a new constraint signature would otherwise compute its start system (seconds, minutes under
// the sanitizers) and be reported as a timeout, which is not what this target hunts.
const relpos::Registry& fuzzRegistry() {
  static const relpos::Registry registry = [] {
    relpos::Registry r;
    relpos::registerBuiltins(r);
    relpos::complete::StageOptions stage;
    stage.compute_start_systems = false;
    // The interval proofs' budgets cut to a tenth: under the sanitizers a box costs about ten
    // times as much, and the full budget of a proof that fails would pass the time limit.
    stage.line_proof_boxes /= 10;
    stage.pose_proof_boxes /= 10;
    relpos::complete::registerStage(r, stage, /*replace=*/true);
    r.freeze();
    return r;
  }();
  return registry;
}

}  // namespace

// Loading a stored start system checks every root (a second under the sanitizers): done once
// here, so the inputs that use one are timed by their solve alone.
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  relpos::complete::preloadStoredStartSystems();
  fuzzRegistry();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace relpos;
  static const Registry& registry = fuzzRegistry();
  // Reused across inputs, as a batch worker reuses them: a solve must not depend on leftovers.
  static Workspace workspace;
  static Solution solution;
  static std::string line;

  const std::string text(reinterpret_cast<const char*>(data), size);
  const ParseResult parsed = parseSpec(text, registry, "fuzz");
  fuzz::Findings findings;
  fuzz::checkDiagnostics(parsed, findings);
  fuzz::checkAccepted(text, parsed, findings);
  if (parsed.problem) {
    const Problem& problem = *parsed.problem;
    solve(problem, registry, SolverOptions(), workspace, solution);
    ReportOptions options;
    options.samples = kSamples;
    options.seed = kSeed;
    writeResultLine(problem, solution, options, line);
    fuzz::ResultExpectation expect;
    expect.samples = kSamples;
    fuzz::checkResultText(line, problem, expect, findings);
    // What the text cannot show: a NaN bound is written as null, like an unbounded one.
    for (std::size_t b = 0; b < solution.branches.size(); ++b)
      for (int i = 0; i < solution.branches[b].manifold->dof(); ++i) {
        const Parameter p = solution.branches[b].manifold->parameter(i);
        if (std::isnan(p.min) || std::isnan(p.max))
          findings.push_back({"bad-output", "branch " + std::to_string(b) + " parameter " +
                                                std::to_string(i) + " has a NaN bound"});
      }
  }
  // Known failures (reported, owned elsewhere) are printed once each and do not stop the run.
  fuzz::Findings fresh;
  for (const auto& f : findings) {
    const fuzz::KnownFailure* known = fuzz::knownFailure(f, text);
    if (!known) {
      fresh.push_back(f);
      continue;
    }
    static std::set<std::string> seen;
    if (seen.insert(known->id).second)
      std::fprintf(stderr, "relpos_spec_fuzzer: known failure %s (not stopping): %s\n", known->id,
                   f.detail.c_str());
  }
  if (fresh.empty()) return 0;
  if (parsed.problem)
    std::fprintf(stderr, "relpos_spec_fuzzer: the result: %s\n",
                 fuzz::printable(line, 4000).c_str());
  fail(fresh);
}
