// The mutation campaign of issue 13's target: ≥ 100,000 mutated specs and batch lines with a
// fixed seed through the checks of the mutation test (cli_checks.hpp) — `relpos batch` on chunks
// of mutated lines, `relpos solve` on mutated files — and every batch line once more in this
// process (parseSpec, solve, writeResultLine: a batch worker's path), timed one by one so that a
// spec slower than a second is flagged. Prints a summary (crashes, hangs, wrong answers, exit-1
// results, split or pathless messages) and saves every failing input under OUT/findings/. Each
// chunk is checked in a child process: a spec that takes the library down in-process (a stack
// overflow, a hang) is then found by bisecting and reported, and the campaign goes on.
// Not part of CI (it takes minutes). Exit 0 when nothing failed, 1 otherwise.
//
//   build/tests/fuzz/relpos_mutation_campaign [--lines N] [--solves N] [--chunk N] [--seed S]
//                                             [--jobs N] [--out DIR]
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
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
    if (s == "--lines")
      a.lines = std::stol(v);
    else if (s == "--solves")
      a.solves = std::stol(v);
    else if (s == "--chunk")
      a.chunk = std::max(1L, std::stol(v));
    else if (s == "--seed")
      a.seed = std::stoull(v);
    else if (s == "--jobs")
      a.jobs = std::stoi(v);
    else if (s == "--out")
      a.out = v;
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

// Runs `work` in a child process that hands its tally back through `file`; false (and how it
// died: "hang" after `timeout_s`, or the signal or exit status) when it did not finish.
bool isolated(const std::function<void(Tally&)>& work, const fs::path& file, int timeout_s,
              Tally& into, std::string* how) {
  fs::remove(file);
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid == 0) {
    alarm(static_cast<unsigned>(timeout_s));
    Tally t;
    t.keep = into.keep;
    work(t);
    t.save(file);
    std::_Exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(file)) {
    into.merge(Tally::load(file));
    return true;
  }
  if (WIFSIGNALED(status))
    *how = WTERMSIG(status) == SIGALRM ? "hang" : "signal " + std::to_string(WTERMSIG(status));
  else
    *how = "exit " + std::to_string(WEXITSTATUS(status));
  return false;
}

using CheckAll = std::function<void(const std::vector<Mutant>&, Tally&)>;
using CheckOne = std::function<void(const Mutant&, Tally&)>;

// The items of [from, to) that take a checking process down on their own.
void locate(const std::vector<Mutant>& items, std::size_t from, std::size_t to, const CheckOne& one,
            const fs::path& file, std::vector<std::size_t>& culprits,
            std::vector<std::string>& hows) {
  Tally scratch;
  std::string how;
  const bool ok = isolated(
      [&](Tally& t) {
        for (std::size_t i = from; i < to; ++i) one(items[i], t);
      },
      file, 600, scratch, &how);
  if (ok) return;
  if (to - from == 1) {
    culprits.push_back(from);
    hows.push_back(how);
    return;
  }
  const std::size_t mid = from + (to - from) / 2;
  locate(items, from, mid, one, file, culprits, hows);
  locate(items, mid, to, one, file, culprits, hows);
}

// Checks the items with `all` in a child process; when it dies, the items that do it alone
// (found with `one`) are reported as crashes or hangs and the rest is checked again without
// them.
void checkIsolated(std::vector<Mutant> items, const CheckAll& all, const CheckOne& one,
                   const fs::path& file, const std::string& where, Tally& tally) {
  for (;;) {
    std::string how;
    if (isolated([&](Tally& t) { all(items, t); }, file, 3600, tally, &how)) return;
    std::vector<std::size_t> culprits;
    std::vector<std::string> hows;
    locate(items, 0, items.size(), one, file, culprits, hows);
    if (culprits.empty()) {
      tally.add({"crash", "the checking process died (" + how + ") only on the whole chunk"},
                items[0], where);
      return;
    }
    for (std::size_t k = culprits.size(); k-- > 0;) {
      tally.add({hows[k] == "hang" ? "hang" : "crash",
                 "checking it in-process (parseSpec, solve, writeResultLine) took the process "
                 "down: " +
                     hows[k]},
                items[culprits[k]], where);
      items.erase(items.begin() + static_cast<std::ptrdiff_t>(culprits[k]));
    }
  }
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
  line_options.max_depth = 300000;
  Mutator lines(a.seed, line_options);
  for (long done = 0; done < a.lines;) {
    std::vector<Mutant> chunk;
    for (; done < a.lines && static_cast<long>(chunk.size()) < a.chunk; ++done)
      chunk.push_back(next(lines, seeds, done));
    const std::string name = "chunk-" + std::to_string(done);
    // The batch, then every line in-process, in a child process. Lines that crash or hang a
    // batch are not run again in-process: they are reported already (found by bisecting).
    checkIsolated(
        chunk,
        [&](const std::vector<Mutant>& lines, Tally& t) {
          std::vector<Mutant> rest;
          checkBatch(o, lines, name, t, &rest);
          for (std::size_t i = 0; i < rest.size(); ++i) {
            const double s = checkInProcess(rest[i], o.samples, o.seed, t);
            t.timed(s, "in-process " + name + ".jsonl:" + std::to_string(i + 1), rest[i], o.slow_s);
          }
        },
        [&](const Mutant& m, Tally& t) { checkInProcess(m, o.samples, o.seed, t); },
        a.out / "tally", "in-process " + name, tally);
    std::cerr << "\rbatch lines " << done << "/" << a.lines << ", failures " << tally.failures()
              << std::flush;
  }
  std::cerr << "\n";
  Mutator files(a.seed + 1, MutationOptions{false, 300000, 0.002});
  constexpr long kSolveChunk = 500;
  for (long done = 0; done < a.solves;) {
    std::vector<Mutant> chunk;
    for (; done < a.solves && static_cast<long>(chunk.size()) < kSolveChunk; ++done)
      chunk.push_back(next(files, seeds, done));
    // The spec file's name: its default name when it has none (the check parses it so too).
    const auto solveOne = [&](const Mutant& m, Tally& t) { checkSolve(o, m, "spec", t); };
    checkIsolated(
        chunk,
        [&](const std::vector<Mutant>& rest, Tally& t) {
          for (const Mutant& m : rest) solveOne(m, t);
        },
        solveOne, a.out / "tally", "solve", tally);
    std::cerr << "\rsolve calls " << done << "/" << a.solves << ", failures " << tally.failures()
              << std::flush;
  }
  std::cerr << "\n";

  // Every failing input kept, one file each, for minimising and tests/fuzz/regressions/.
  fs::create_directories(a.out / "findings");
  for (std::size_t i = 0; i < tally.reports.size(); ++i) {
    const Report& r = tally.reports[i];
    const std::string stem = std::to_string(i) + "-" + r.finding.kind;
    std::ofstream(a.out / "findings" / (stem + ".json"), std::ios::binary) << r.input.text;
    std::ofstream(a.out / "findings" / (stem + ".txt"))
        << r.command << "\n"
        << r.finding.detail << "\nfrom " << r.input.origin
        << " by: " << printable(r.input.edits, 2000) << "\n";
  }
  fs::remove_all(o.dir);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "relpos mutation campaign: seed " << a.seed << ", " << a.lines << " batch lines in "
            << (a.lines + a.chunk - 1) / a.chunk << " batches, " << a.solves << " solve calls, "
            << seconds << " s\n"
            << tally.text(30) << "failures: " << tally.failures() << " (inputs in "
            << (a.out / "findings").string() << ")\n";
  return tally.failures() == 0 ? 0 : 1;
}
