// The numeric stage (docs/spec.md §8.7, §8.8) on random problems of 2-4 constraints with ranges
// built around a known pose (the tests' generator): the problems the rules alone leave, each
// solved in turn, one per iteration; the median and 99th percentile of a solve are counters.
// The start systems a 0-DOF family computes on first use (§8.5, once per process) are computed
// before timing — the first solve of a new signature costs 0.1–5 s more. And, for comparison,
// the problems the rules answer.
//   build/bench/relpos_fallback_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "ranged_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "test_fallback.hpp"

namespace {

using relpos::Problem;

// The random problems, those the rules leave (`left`) or answer.
std::vector<Problem> randomProblems(bool left) {
  relpos::test::Rng rng(2016);
  std::vector<Problem> out;
  for (int i = 0; i < 600; ++i) {
    const relpos::test::KnownProblem kp = relpos::test::randomRangedProblem(rng, i % 2 == 1);
    const relpos::Solution rules = relpos::solve(kp.problem, relpos::test::rulesOnlyRegistry());
    if ((rules.status == relpos::Status::kUnhandled) != left) continue;
    relpos::solve(kp.problem, relpos::builtinRegistry());  // start systems computed here
    out.push_back(kp.problem);
  }
  return out;
}

void BM_Random(benchmark::State& state, bool left) {
  static const std::vector<Problem> fallback = randomProblems(true);
  static const std::vector<Problem> closed = randomProblems(false);
  const std::vector<Problem>& problems = left ? fallback : closed;
  relpos::Workspace ws;
  relpos::Solution s;
  std::vector<double> micros;
  std::size_t next = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    relpos::solve(problems[next], relpos::builtinRegistry(), relpos::SolverOptions(), ws, s);
    micros.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    benchmark::DoNotOptimize(s.branches.data());
    next = (next + 1) % problems.size();
  }
  std::sort(micros.begin(), micros.end());
  state.counters["problems"] = static_cast<double>(problems.size());
  state.counters["median_us"] = micros[micros.size() / 2];
  state.counters["p99_us"] = micros[micros.size() * 99 / 100];
}

BENCHMARK_CAPTURE(BM_Random, left_by_the_rules_2_4_constraints_ranges, true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Random, answered_by_the_rules_2_4_constraints_ranges, false)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
