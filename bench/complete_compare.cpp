// The benchmark problems of the complete solvers side by side (issue 15), in one program and one
// run: for each spec in data/complete, relpos::solve's median time (Google Benchmark), PHCpack's
// blackbox solver `phc -b` and its parameter homotopy `phc -p` from a cached start system of the
// same family (subprocesses on generated input files, wall clock), and the poses each found
// against the known set (the tests' random-start Newton reference, checked by the tests'
// evaluator), and what relpos certified.
//   build/bench/relpos_complete_compare [--phc-runs=N] [--cache=DIR] [benchmark flags]
// Without `phc` on PATH (Debian: apt-get install phcpack) the PHC columns say so.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "complete/phc_runner.hpp"
#include "complete/phc_systems.hpp"
#include "completeness_fields.hpp"
#include "interval_check.hpp"
#include "reference_roots.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"

namespace {

using relpos::bench::Family;
namespace fs = std::filesystem;

struct Row {
  std::string name;
  relpos::Problem problem;
  bool line_quotient = false;
  relpos::test::ReferenceRoots reference;
  double relpos_ms = -1.0;
  std::string relpos_status;
  int relpos_found = 0, certified = 0;
  std::string complete = "n/a";
  std::vector<double> phc_b_s, phc_p_s;
  std::vector<int> phc_b_found, phc_p_found;
};

std::vector<Row>& rows() {
  static std::vector<Row> r;
  return r;
}

void BM_Solve(benchmark::State& state, std::size_t i) {
  const relpos::Problem& p = rows()[i].problem;
  relpos::Workspace ws;
  relpos::Solution s;
  for (auto _ : state) {
    relpos::solve(p, relpos::builtinRegistry(), relpos::SolverOptions(), ws, s);
    benchmark::DoNotOptimize(s.branches.data());
  }
  state.counters["branches"] = static_cast<double>(s.branches.size());
  state.SetLabel(relpos::toString(s.status));
}

// Keeps each benchmark's median (the aggregate Google Benchmark computes over the repetitions).
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    // With one repetition there is no aggregate: the run itself stands for the median.
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Aggregate ? r.aggregate_name == "median"
                                          : !medians.count(r.run_name.function_name))
        medians[r.run_name.function_name] = r.GetAdjustedRealTime();
  }
  std::map<std::string, double> medians;  // in the benchmark's unit (ms)
};

// How many known roots a list of poses holds (each known root matched by some pose).
int foundOf(const Row& row, const std::vector<relpos::Isometry3d>& poses) {
  int found = 0;
  for (const relpos::Isometry3d& X : row.reference.poses) {
    bool hit = false;
    for (const relpos::Isometry3d& Y : poses) {
      const double d = row.line_quotient ? relpos::test::lineDistance(
                                               relpos::test::undirectedLine(row.problem, X),
                                               relpos::test::undirectedLine(row.problem, Y))
                                         : relpos::poseDistance(X, Y);
      hit = hit || d < 1e-5;
    }
    found += hit;
  }
  return found;
}

void relposAnswer(Row& row) {
  const relpos::Solution s = relpos::solve(row.problem, relpos::builtinRegistry());
  row.relpos_status = relpos::toString(s.status);
  std::vector<relpos::Isometry3d> poses;
  for (const relpos::Branch& b : s.branches) {
    const relpos::Isometry3d X = b.manifold->pose(relpos::referenceParams(*b.manifold));
    poses.push_back(X);
    const auto proof = relpos::test::proofOf(b);
    if (!proof || proof->exact || !(proof->radius > 0)) continue;
    const relpos::test::IntervalBox box =
        relpos::test::certificateBox(proof->radius, proof->angle, row.line_quotient);
    row.certified += relpos::test::provesSolutionWithin(row.problem, X, box).proven;
  }
  row.relpos_found = foundOf(row, poses);
  if (const auto c = relpos::test::completeOf(s)) row.complete = *c ? "yes" : "no";
}

void phcColumns(Row& row, const std::string& phc, const std::string& cache, int runs) {
  Family family;
  if (!relpos::bench::familyOf(row.problem, &family)) return;
  const relpos::bench::PolySystem target = relpos::bench::targetSystem(row.problem, family);
  const std::string dir = (fs::temp_directory_path() / "relpos-complete-compare").string();
  fs::create_directories(dir);
  int start_roots = 0;
  double start_s = 0.0;
  std::string error;
  const std::string start =
      relpos::bench::startSystem(phc, cache, family, &start_roots, &start_s, &error);
  // phc -p tracks one path per root of the start system: a start that lost a root loses poses.
  const char* fam = family == Family::kPointDistances ? "point-distance" : "line-distance";
  if (start_s > 0)
    std::printf("  %s: made the %s start system: %d roots, %.2f s by phc -b, cached in %s\n",
                row.name.c_str(), fam, start_roots, start_s, cache.c_str());
  else if (!start.empty())
    std::printf("  %s: the cached %s start system, %d roots\n", row.name.c_str(), fam, start_roots);
  auto posesOf = [&](const relpos::bench::PhcRun& run) {
    std::vector<relpos::Isometry3d> poses;
    for (const std::vector<double>& x : run.real_roots) {
      relpos::Isometry3d X;
      if (relpos::bench::poseOfSolution(row.problem, family, x, &X)) poses.push_back(X);
    }
    return poses;
  };
  for (int k = 0; k < runs; ++k) {
    const relpos::bench::PhcRun b = relpos::bench::phcBlackbox(phc, dir, row.name, target);
    if (!b.error.empty()) std::printf("  %s: phc -b: %s\n", row.name.c_str(), b.error.c_str());
    row.phc_b_s.push_back(b.seconds);
    row.phc_b_found.push_back(foundOf(row, posesOf(b)));
    if (start.empty()) {
      std::printf("  %s: no start system for phc -p: %s\n", row.name.c_str(), error.c_str());
      continue;
    }
    const relpos::bench::PhcRun p = relpos::bench::phcParameter(phc, dir, row.name, target, start);
    if (!p.error.empty()) std::printf("  %s: phc -p: %s\n", row.name.c_str(), p.error.c_str());
    row.phc_p_s.push_back(p.seconds);
    row.phc_p_found.push_back(foundOf(row, posesOf(p)));
  }
}

// "0.43" for one run, "0.41-0.46" for several; found "40" or "39-40".
std::string span(const std::vector<double>& v, const char* fmt) {
  if (v.empty()) return "-";
  double lo = v[0], hi = v[0];
  for (double x : v) lo = std::min(lo, x), hi = std::max(hi, x);
  char a[32], b[32];
  std::snprintf(a, sizeof a, fmt, lo);
  std::snprintf(b, sizeof b, fmt, hi);
  return lo == hi ? std::string(a) : std::string(a) + "-" + b;
}
std::string spanFound(const std::vector<int>& v, std::size_t known) {
  if (v.empty()) return "-";
  std::vector<double> d(v.begin(), v.end());
  return span(d, "%.0f") + "/" + std::to_string(known);
}

}  // namespace

int main(int argc, char** argv) {
  int phc_runs = 1;
  std::string cache =
      fs::absolute(fs::path(argv[0]).parent_path() / "complete_compare_cache").string();
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], "--phc-runs=", 11) == 0) {
      phc_runs = std::max(1, std::atoi(argv[i] + 11));
    } else if (std::strncmp(argv[i], "--cache=", 8) == 0) {
      cache = argv[i] + 8;
    } else {
      rest.push_back(argv[i]);
    }
  }
  for (const char* f :
       {"stewart-gough-dietmaier-40", "octahedral-a", "octahedral-b", "four-spheres-12-lines"}) {
    const std::string file = RELPOS_DATA_DIR "/complete/" + std::string(f) + ".json";
    relpos::ParseResult r = relpos::parseSpecFile(file, relpos::builtinRegistry());
    if (!r.problem) {
      std::fprintf(stderr, "cannot read %s\n", file.c_str());
      return 2;
    }
    Row row;
    row.name = f;
    row.problem = *r.problem;
    Family family;  // the mobile object one line: its spin and slide are free
    row.line_quotient =
        relpos::bench::familyOf(row.problem, &family) && family == Family::kLineDistances;
    relpos::test::ReferenceOptions o;
    o.starts = 6000;
    o.seed = 20261202;
    o.line_quotient = row.line_quotient;
    row.reference = relpos::test::referenceRoots(row.problem, o);
    rows().push_back(row);
  }

  // relpos: Google Benchmark, the median of the repetitions.
  int bargc = static_cast<int>(rest.size());
  std::vector<char*> bargv = rest;
  std::string reps = "--benchmark_repetitions=5";
  bool has_reps = false;
  for (char* a : rest) has_reps = has_reps || std::strncmp(a, "--benchmark_repetitions", 23) == 0;
  if (!has_reps) {
    bargv.push_back(reps.data());
    ++bargc;
  }
  for (std::size_t i = 0; i < rows().size(); ++i)
    benchmark::RegisterBenchmark(("solve/" + rows()[i].name).c_str(), BM_Solve, i)
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&bargc, bargv.data());
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  for (Row& row : rows()) {
    const auto it = reporter.medians.find("solve/" + row.name);
    if (it != reporter.medians.end()) row.relpos_ms = it->second;
    relposAnswer(row);
  }

  const std::string phc = relpos::bench::findPhc();
  if (phc.empty()) {
    std::printf(
        "\nphc is not on PATH: the PHCpack columns are skipped (Debian: apt-get install "
        "phcpack).\n");
  } else {
    std::printf("\nPHCpack: %s, %d run(s) of phc -b and phc -p per problem\n", phc.c_str(),
                phc_runs);
    for (Row& row : rows()) phcColumns(row, phc, cache, phc_runs);
  }

  std::printf("\n%-28s %10s %-10s %10s %10s %9s %6s %7s %7s %7s %9s %8s\n", "problem", "relpos ms",
              "status", "phc -b s", "phc -p s", "p/relpos", "known", "relpos", "phc -b", "phc -p",
              "certified", "complete");
  for (const Row& row : rows()) {
    char ms[32] = "-";  // not measured (filtered out)
    if (row.relpos_ms >= 0) std::snprintf(ms, sizeof ms, "%.3f", row.relpos_ms);
    const std::size_t known = row.reference.poses.size();
    // How many times faster than phc -p (its fastest run): only for an answer relpos gave.
    char ratio[32] = "-";
    if (row.relpos_status == "solved" && row.relpos_ms > 0 && !row.phc_p_s.empty())
      std::snprintf(
          ratio, sizeof ratio, "%.0fx",
          *std::min_element(row.phc_p_s.begin(), row.phc_p_s.end()) * 1e3 / row.relpos_ms);
    std::printf("%-28s %10s %-10s %10s %10s %9s %6zu %7s %7s %7s %9s %8s\n", row.name.c_str(), ms,
                row.relpos_status.c_str(), span(row.phc_b_s, "%.2f").c_str(),
                span(row.phc_p_s, "%.2f").c_str(), ratio, known,
                (std::to_string(row.relpos_found) + "/" + std::to_string(known)).c_str(),
                spanFound(row.phc_b_found, known).c_str(),
                spanFound(row.phc_p_found, known).c_str(),
                (std::to_string(row.certified) + "/" + std::to_string(known)).c_str(),
                row.complete.c_str());
  }
  std::printf(
      "\nknown: distinct real roots of 6000 random-start Newton solves, each verified by the "
      "tests' evaluator (for four spheres: lines). relpos/phc: known roots each found (within "
      "1e-5). certified: relpos branches whose certificate the tests' interval check re-proves. "
      "complete: relpos's Solution::complete (n/a before the field exists). PHC: real "
      "solutions of its Study-parameter (lines: Plücker) system, wall clock of the subprocess; "
      "neither certifies nor proves completeness.\n");
  return 0;
}
