// solve() on every bundled example (each single-constraint kind, the PMF worked example, the
// two-constraint cases, PMF's assembly task), on data/bench (five constraints, 16 branches) and
// on the engineers' tasks of data/tasks (closed forms, and charts where the rules leave them:
// the label says which),
// into a reused Workspace and Solution as a control loop would call it; and the nearest pose of
// every branch of each (`nearest/…`), to the mobile object's pose in the file.
//   build/bench/relpos_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"

namespace {

relpos::Problem load(const std::string& file) {
  relpos::ParseResult r = relpos::parseSpecFile(file, relpos::builtinRegistry());
  if (!r.problem) throw std::runtime_error("cannot parse " + file);
  return *r.problem;
}

void BM_Solve(benchmark::State& state, const std::string& file) {
  const relpos::Problem p = load(file);
  relpos::Workspace ws;
  relpos::Solution s;
  for (auto _ : state) {
    relpos::solve(p, relpos::builtinRegistry(), relpos::SolverOptions(), ws, s);
    benchmark::DoNotOptimize(s.branches.data());
  }
  state.counters["branches"] = static_cast<double>(s.branches.size());
  const bool numeric = std::any_of(s.branches.begin(), s.branches.end(),
                                   [](const relpos::Branch& b) { return !b.exact; });
  state.SetLabel(std::string(relpos::toString(s.status)) + (numeric ? " (numeric stage)" : ""));
}

// The nearest pose of every branch of a solved example, to its mobile object's current pose.
void BM_NearestOfEveryBranch(benchmark::State& state, const std::string& file) {
  const relpos::Problem p = load(file);
  const relpos::Solution s = relpos::solve(p, relpos::builtinRegistry());
  for (auto _ : state)
    for (const auto& b : s.branches)
      benchmark::DoNotOptimize(relpos::nearestOnBranch(b, p.mobile.pose).distance);
  state.counters["branches"] = static_cast<double>(s.branches.size());
}

void BM_NearestWorkedExample(benchmark::State& state) {
  const relpos::Problem p = load(RELPOS_DATA_DIR "/examples/pmf-simple-example.json");
  relpos::Solution s = relpos::solve(p, relpos::builtinRegistry());
  for (auto _ : state) {
    relpos::NearestPose n = relpos::nearestOnBranch(s.branches[0], p.mobile.pose);
    benchmark::DoNotOptimize(n.distance);
  }
}
BENCHMARK(BM_NearestWorkedExample);

int registerExamples() {
  std::vector<std::string> files;
  for (const char* dir : {RELPOS_DATA_DIR "/examples", RELPOS_DATA_DIR "/bench",
                          RELPOS_DATA_DIR "/scenarios", RELPOS_DATA_DIR "/tasks"})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".json" && e.path().filename() != "expected.json")
        files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const auto& f : files)
    benchmark::RegisterBenchmark(("solve/" + std::filesystem::path(f).stem().string()).c_str(),
                                 BM_Solve, f);
  for (const auto& f : files)
    benchmark::RegisterBenchmark(("nearest/" + std::filesystem::path(f).stem().string()).c_str(),
                                 BM_NearestOfEveryBranch, f);
  return 0;
}
const int kRegistered = registerExamples();

}  // namespace

BENCHMARK_MAIN();
