// The numeric engine of issue 15 on the 6-6 Stewart–Gough family (tests/complete/
// test_families.*): solveFiber on a real target (40 paths tracked and certified), its tracking
// and certification apart, and startSystem (monodromy + total-degree check) on a fresh signature.
#include <benchmark/benchmark.h>

#include "homotopy.hpp"
#include "krawczyk.hpp"
#include "random.hpp"
#include "relpos/complete/fiber.hpp"
#include "test_families.hpp"

namespace {

using namespace relpos::complete;

const testing::StewartFamily& family() {
  static const testing::StewartFamily f;
  return f;
}

std::vector<double> target(std::uint64_t seed) {
  testing::StewartPose pose;
  return testing::randomStewartMember(seed, pose);
}

void BM_SolveFiberStewart(benchmark::State& state) {
  const auto t = target(23);
  startSystem(family());
  int complete = 0, runs = 0;
  for (auto _ : state) {
    FiberOptions options;
    options.threads = static_cast<int>(state.range(0));
    const FiberResult r = solveFiber(family(), t, options);
    complete += r.complete ? 1 : 0;
    ++runs;
    benchmark::DoNotOptimize(r.roots.data());
  }
  state.counters["complete"] = double(complete) / runs;
}
BENCHMARK(BM_SolveFiberStewart)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// Tracking only (one γ, 40 paths) and certification only (40 endpoints).
void BM_TrackStewart(benchmark::State& state) {
  const StartSystem& s = startSystem(family());
  const auto t = target(23);
  const detail::CompiledShape shape(family().shape());
  std::vector<Complex> p1(t.begin(), t.end()), c1(shape.terms());
  family().coefficients(p1.data(), c1.data());
  const auto poly = detail::interpolateSegment(family(), s.params.data(), p1.data());
  detail::Tracker tracker(shape, poly, detail::Arc{detail::randomGamma(detail::mixSeed(1, 0))},
                          c1.data());
  int steps = 0, paths = 0;
  for (auto _ : state)
    for (const auto& r : s.roots) {
      const detail::PathEnd e = tracker.track(detail::CVec(r));
      steps += e.steps;
      ++paths;
      benchmark::DoNotOptimize(e.x.data());
    }
  state.counters["steps/path"] = double(steps) / paths;
}
BENCHMARK(BM_TrackStewart)->Unit(benchmark::kMillisecond);

void BM_CertifyStewart(benchmark::State& state) {
  const auto t = target(23);
  const FiberResult r = solveFiber(family(), t);
  const detail::CompiledShape shape(family().shape());
  std::vector<Interval> ip(t.begin(), t.end()), ic(shape.terms());
  family().coefficients(ip.data(), ic.data());
  detail::Certifier certifier(shape, ic.data());
  for (auto _ : state)
    for (const auto& root : r.roots) {
      const auto c = certifier.certify(detail::CVec(root.x));
      benchmark::DoNotOptimize(c.radius);
    }
}
BENCHMARK(BM_CertifyStewart)->Unit(benchmark::kMillisecond);

void BM_StartSystemStewart(benchmark::State& state) {
  int k = 0;
  for (auto _ : state) {
    const testing::StewartFamily f("bench:stewart-" + std::to_string(k++));
    const StartSystem& s = startSystem(f);
    state.counters["roots"] = double(s.roots.size());
    state.counters["loops"] = s.monodromy_loops;
  }
}
BENCHMARK(BM_StartSystemStewart)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
