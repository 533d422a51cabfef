// The mutation campaign of issue 13's target: ≥ 100,000 mutated specs and batch lines with a
// fixed seed through the checks of the mutation test (cli_checks.hpp) — `relpos batch` on chunks
// of mutated lines, `relpos solve` on mutated files — and every batch line once more in this
// process (parseSpec, solve, writeResultLine: a batch worker's path), timed one by one so that a
// spec slower than a second is flagged. Prints a summary (crashes, hangs, wrong answers, exit-1
// results, split or pathless messages) and saves every failing input under OUT/findings/.
// Not part of CI (it takes minutes). Exit 0 when nothing failed, 1 otherwise.
//
//   build/tests/fuzz/relpos_mutation_campaign [--lines N] [--solves N] [--chunk N] [--seed S]
//                                             [--jobs N] [--out DIR]
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "cli_checks.hpp"
#include "mutator.hpp"
#include "test_config.hpp"

namespace fs = std::filesystem;
using namespace relpos::fuzz;

namespace {

struct Args {
  long lines = 100000, solves = 5000, chunk = 5000;
  std::uint64_t seed = 20240613;
  int jobs = 2;
  fs::path out = fs::temp_directory_path() / "relpos_mutation_campaign";
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "relpos_mutation_campaign: " << s << ": missing value\n";
      std::exit(2);
    }
    const std::string v = argv[++i];
    if (s == "--lines") a.lines = std::stol(v);
    else if (s == "--solves") a.solves = std::stol(v);
    else if (s == "--chunk") a.chunk = std::max(1L, std::stol(v));
    else if (s == "--seed") a.seed = std::stoull(v);
    else if (s == "--jobs") a.jobs = std::stoi(v);
    else if (s == "--out") a.out = v;
    else {
      std::cerr << "relpos_mutation_campaign: unknown option '" << s << "'\n";
      std::exit(2);
    }
  }
  return a;
}

Mutant next(Mutator& m, const std::vector<Seed>& seeds, long i) {
  const Seed& s = seeds[static_cast<std::size_t>(i) % seeds.size()];
  Mutant x;
  x.origin = s.origin;
  x.text = m.mutate(s.tree, "m" + std::to_string(i), &x.edits);
  return x;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Seed> seeds = loadSeeds(RELPOS_DATA_DIR);
  fs::remove_all(a.out);
  fs::create_directories(a.out / "work");
  CliOptions o;
  o.exe = RELPOS_EXE;
  o.dir = a.out / "work";
  o.jobs = a.jobs;
  Tally tally;
  tally.keep = 1000;

  // Batch lines: mutated in chunks (one batch process each), then each line in this process.
  MutationOptions line_options;
  line_options.one_line = true;
  line_options.max_depth = 100000;
  Mutator lines(a.seed, line_options);
  double in_process_s = 0;
  for (long done = 0; done < a.lines;) {
    std::vector<Mutant> chunk;
    for (; done < a.lines && static_cast<long>(chunk.size()) < a.chunk; ++done)
      chunk.push_back(next(lines, seeds, done));
    const std::string name = "chunk-" + std::to_string(done);
    // A chunk whose batch crashed or hung is not run again here (it would take this process
    // down): its culprits are already found by bisecting.
    if (checkBatch(o, chunk, name, tally))
      for (std::size_t i = 0; i < chunk.size(); ++i) {
        const double s = checkInProcess(chunk[i], o.samples, o.seed, tally);
        in_process_s += s;
        tally.timed(s, "in-process " + name + ".jsonl:" + std::to_string(i + 1), chunk[i],
                    o.slow_s);
      }
    std::cerr << "\rbatch lines " << done << "/" << a.lines << ", failures " << tally.failures()
              << std::flush;
  }
  std::cerr << "\n";
  Mutator files(a.seed + 1, MutationOptions{false, 100000, 0.002});
  for (long i = 0; i < a.solves; ++i) {
    checkSolve(o, next(files, seeds, i), "spec-" + std::to_string(i % 100), tally);
    if (i % 100 == 99)
      std::cerr << "\rsolve calls " << i + 1 << "/" << a.solves << ", failures "
                << tally.failures() << std::flush;
  }
  std::cerr << "\n";

  // Every failing input kept, one file each, for minimising and tests/fuzz/regressions/.
  fs::create_directories(a.out / "findings");
  for (std::size_t i = 0; i < tally.reports.size(); ++i) {
    const Report& r = tally.reports[i];
    const std::string stem = std::to_string(i) + "-" + r.finding.kind;
    std::ofstream(a.out / "findings" / (stem + ".json"), std::ios::binary) << r.input.text;
    std::ofstream(a.out / "findings" / (stem + ".txt"))
        << r.command << "\n" << r.finding.detail << "\nfrom " << r.input.origin << " by: "
        << printable(r.input.edits, 2000) << "\n";
  }
  fs::remove_all(o.dir);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "relpos mutation campaign: seed " << a.seed << ", " << a.lines << " batch lines in "
            << (a.lines + a.chunk - 1) / a.chunk << " batches, " << a.solves
            << " solve calls, " << seconds << " s (in-process parse+solve+write: " << in_process_s
            << " s)\n"
            << tally.text(30) << "failures: " << tally.failures() << " (inputs in "
            << (a.out / "findings").string() << ")\n";
  return tally.failures() == 0 ? 0 : 1;
}
