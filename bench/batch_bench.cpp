// What one batch line costs, stage by stage, on the bundled generated grasp and weld specs
// (data/batch): parsing the spec text, solving, the nearest pose of every branch, and writing the
// result line. One thread; `relpos batch --jobs N` runs N of these pipelines.
//   build/bench/relpos_batch_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>
#include <vector>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"

namespace {

const std::vector<std::string>& lines() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v;
    std::ifstream in(RELPOS_DATA_DIR "/batch/grasp-and-weld-100.jsonl");
    for (std::string line; std::getline(in, line);) v.push_back(line);
    return v;
  }();
  return all;
}

void BM_Parse(benchmark::State& state) {
  std::size_t i = 0;
  for (auto _ : state) {
    relpos::ParseResult r =
        relpos::parseSpec(lines()[i++ % lines().size()], relpos::builtinRegistry());
    benchmark::DoNotOptimize(r.problem);
  }
}
BENCHMARK(BM_Parse);

std::vector<relpos::Problem> problems() {
  std::vector<relpos::Problem> v;
  for (const auto& l : lines())
    v.push_back(*relpos::parseSpec(l, relpos::builtinRegistry()).problem);
  return v;
}

void BM_Solve(benchmark::State& state) {
  const auto ps = problems();
  relpos::Workspace ws;
  relpos::Solution s;
  std::size_t i = 0;
  for (auto _ : state) {
    relpos::solve(ps[i++ % ps.size()], relpos::builtinRegistry(), relpos::SolverOptions(), ws, s);
    benchmark::DoNotOptimize(s.branches.data());
  }
}
BENCHMARK(BM_Solve);

void BM_NearestOfEveryBranch(benchmark::State& state) {
  const auto ps = problems();
  std::vector<relpos::Solution> sols;
  for (const auto& p : ps) sols.push_back(relpos::solve(p, relpos::builtinRegistry()));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % ps.size();
    for (const auto& b : sols[k].branches)
      benchmark::DoNotOptimize(relpos::nearestOnBranch(b, ps[k].mobile.pose).distance);
  }
}
BENCHMARK(BM_NearestOfEveryBranch);

// The same per kind of generated spec (its name's prefix), to see which manifold costs what.
void BM_NearestByKind(benchmark::State& state, const std::string& prefix) {
  std::vector<relpos::Problem> ps;
  std::vector<relpos::Solution> sols;
  for (const auto& p : problems())
    if (p.name.rfind(prefix, 0) == 0) {
      ps.push_back(p);
      sols.push_back(relpos::solve(p, relpos::builtinRegistry()));
    }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % ps.size();
    for (const auto& b : sols[k].branches)
      benchmark::DoNotOptimize(relpos::nearestOnBranch(b, ps[k].mobile.pose).distance);
  }
}
BENCHMARK_CAPTURE(BM_NearestByKind, cylinder, std::string("cylinder-grasp"));
BENCHMARK_CAPTURE(BM_NearestByKind, cup, std::string("cup-grasp"));
BENCHMARK_CAPTURE(BM_NearestByKind, tray, std::string("tray-grasp"));
BENCHMARK_CAPTURE(BM_NearestByKind, weld, std::string("weld-seam"));

// The nearest pose in a tracking loop: the tool's orientation already one of the branch's, its
// position 4.9 cm off (the branch's pose at its reference parameters, moved). Where the branch's
// positions move less than a length unit a radian with its rotation (a torch tip, a fingertip
// 0.1-0.3 from the origin), the answer keeps the rotation, proven, without a search (spec §2.6).
void BM_NearestTrackingByKind(benchmark::State& state, const std::string& prefix) {
  std::vector<relpos::Solution> sols;
  for (const auto& p : problems())
    if (p.name.rfind(prefix, 0) == 0) sols.push_back(relpos::solve(p, relpos::builtinRegistry()));
  std::vector<const relpos::Branch*> branches;
  std::vector<relpos::Isometry3d> poses;
  for (const auto& s : sols)
    for (const auto& b : s.branches) {
      relpos::Isometry3d X = b.manifold->pose(relpos::referenceParams(*b.manifold));
      X.translation() += relpos::Vector3d(0.03, -0.02, 0.034);
      branches.push_back(&b);
      poses.push_back(X);
    }
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % branches.size();
    benchmark::DoNotOptimize(relpos::nearestOnBranch(*branches[k], poses[k]).distance);
  }
}
BENCHMARK_CAPTURE(BM_NearestTrackingByKind, cylinder, std::string("cylinder-grasp"));
BENCHMARK_CAPTURE(BM_NearestTrackingByKind, weld, std::string("weld-seam"));

// Writing the result line alone (no parse, no solve): the problems are solved once up front.
void BM_Write(benchmark::State& state) {
  const auto ps = problems();
  std::vector<relpos::Solution> sols;
  for (const auto& p : ps) sols.push_back(relpos::solve(p, relpos::builtinRegistry()));
  std::string out;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % ps.size();
    relpos::writeResultLine(ps[k], sols[k], relpos::ReportOptions(), out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_Write);

void BM_WholeLine(benchmark::State& state) {
  relpos::Workspace ws;
  relpos::Solution s;
  std::string out;
  std::size_t i = 0;
  for (auto _ : state) {
    relpos::ParseResult r =
        relpos::parseSpec(lines()[i++ % lines().size()], relpos::builtinRegistry());
    relpos::solve(*r.problem, relpos::builtinRegistry(), relpos::SolverOptions(), ws, s);
    relpos::writeResultLine(*r.problem, s, relpos::ReportOptions(), out);
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_WholeLine);

}  // namespace

BENCHMARK_MAIN();
