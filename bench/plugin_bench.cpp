// What plugins cost. Start-up: a fresh registry with the built-ins, then the same plus each
// example plugin loaded (dlopen, ABI check, registration; the library is unloaded again at the end
// of every iteration, so each load is a real one). Hot path: solving the plugin specs with a
// registry holding the plugins, beside built-in problems of the same shape — plugin items are
// reached through the same registry table as built-ins, with no extra indirection.
//   build/bench/relpos_plugin_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <stdexcept>
#include <string>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/loader.hpp"

namespace {

const std::string kSymmetric = RELPOS_PLUGIN_DIR "/relpos-symmetric.so";
const std::string kHelical = RELPOS_PLUGIN_DIR "/relpos-helical.so";

void load(const std::string& path, relpos::Registry& r) {
  std::string error;
  if (!relpos::plugins::loadPlugin(path, r, &error)) throw std::runtime_error(error);
}

void BM_StartupBuiltinsOnly(benchmark::State& state) {
  for (auto _ : state) {
    relpos::Registry r;
    relpos::registerBuiltins(r);
    benchmark::DoNotOptimize(r.rules().data());
  }
}
BENCHMARK(BM_StartupBuiltinsOnly)->Unit(benchmark::kMicrosecond);

void BM_StartupWithPlugin(benchmark::State& state, const std::string& path) {
  for (auto _ : state) {
    relpos::Registry r;
    relpos::registerBuiltins(r);
    load(path, r);
    benchmark::DoNotOptimize(r.rules().data());
  }
}
BENCHMARK_CAPTURE(BM_StartupWithPlugin, symmetric, kSymmetric)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_StartupWithPlugin, helical, kHelical)->Unit(benchmark::kMicrosecond);

const relpos::Registry& withPlugins() {
  static const relpos::Registry reg = [] {
    relpos::Registry r;
    relpos::registerBuiltins(r);
    load(kSymmetric, r);
    load(kHelical, r);
    r.freeze();
    return r;
  }();
  return reg;
}

void BM_Solve(benchmark::State& state, const std::string& file) {
  relpos::ParseResult parsed = relpos::parseSpecFile(file, withPlugins());
  if (!parsed.problem) throw std::runtime_error("cannot parse " + file);
  relpos::Workspace ws;
  relpos::Solution s;
  for (auto _ : state) {
    relpos::solve(*parsed.problem, withPlugins(), relpos::SolverOptions(), ws, s);
    benchmark::DoNotOptimize(s.branches.data());
  }
  state.SetLabel(relpos::toString(s.status));
}
// Plugin items, and built-in problems of a similar size and shape for comparison.
BENCHMARK_CAPTURE(BM_Solve, plugin_symmetric_centred_grasp,
                  RELPOS_DATA_DIR "/plugins/symmetric-centred-grasp.json");
BENCHMARK_CAPTURE(BM_Solve, plugin_helical_screw_insertion,
                  RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json");
BENCHMARK_CAPTURE(BM_Solve, builtin_range_fingertip_near_axis,
                  RELPOS_DATA_DIR "/examples/range-fingertip-near-axis.json");
BENCHMARK_CAPTURE(BM_Solve, builtin_coincident_axis_line,
                  RELPOS_DATA_DIR "/examples/coincident-axis-line.json");

}  // namespace

BENCHMARK_MAIN();
