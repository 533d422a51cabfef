// Thousands of structured mutations of the specs in data/ (fixed seed) through the real `relpos`
// executable: `batch` on JSONL files of mutated lines and `solve` on mutated files. Whatever the
// input: exit 0 or 2 (never 1, never a signal, never a hang); one stderr line per diagnostic,
// naming the file and a JSON path (or "malformed JSON at line L, column C"); one result line per
// input line, in order, each a valid UTF-8 JSON document; invalid lines carry FILE:LINE; and
// every pose of every solved branch (nearest and samples) satisfies every constraint of the
// mutated spec by the tests' evaluator. The ≥ 100,000-spec campaign runs the same checks:
// build/tests/fuzz/relpos_mutation_campaign.
#include <gtest/gtest.h>
#include <unistd.h>

#include "cli_checks.hpp"
#include "mutator.hpp"
#include "slow_tests.hpp"
#include "test_config.hpp"

namespace relpos::fuzz {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 20240613;
// A quarter under sanitizers (sweepCount): there each relpos process takes 0.2 s to start.
constexpr int kBatchLines = test::sweepCount(10000);  // in two batch processes
constexpr int kSolveCalls = test::sweepCount(300);

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("relpos_mutation_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

CliOptions options(const std::string& name) {
  CliOptions o;
  o.exe = RELPOS_EXE;
  o.dir = scratch(name);
  return o;
}

const std::vector<Seed>& seeds() {
  static const std::vector<Seed> s = loadSeeds(RELPOS_DATA_DIR);
  return s;
}

// The mutants, cycling through the seeds; each named after its index.
std::vector<Mutant> mutants(int n, std::uint64_t seed, const MutationOptions& mo) {
  Mutator m(seed, mo);
  std::vector<Mutant> out;
  for (int i = 0; i < n; ++i) {
    const Seed& s = seeds()[static_cast<std::size_t>(i) % seeds().size()];
    Mutant x;
    x.origin = s.origin;
    x.text = m.mutate(s.tree, "m" + std::to_string(i), &x.edits);
    out.push_back(std::move(x));
  }
  return out;
}

TEST(Mutation, SeedsCoverTheData) {
  // Every spec of data/ and every line of its batch files (a test that reads none checks nothing).
  EXPECT_GT(seeds().size(), 200u);
}

// No failure; and the mutations reached the solver, not only the reader: of n inputs, many stay
// valid specs and many are refused.
void expectCleanAndVaried(Tally& tally, int n) {
  EXPECT_EQ(tally.failures(), 0) << tally.text();
  EXPECT_GT(tally.statuses["solved"], n / 10) << tally.text();
  EXPECT_GT(tally.statuses["invalid"], n / 10) << tally.text();
  std::cout << tally.text(0);
}

TEST(Mutation, BatchOfMutatedLinesKeepsEveryInvariant) {
  MutationOptions mo;
  mo.one_line = true;
  const std::vector<Mutant> lines = mutants(kBatchLines, kSeed, mo);
  const CliOptions o = options("batch");
  Tally tally;
  const auto half = lines.begin() + kBatchLines / 2;
  checkBatch(o, std::vector<Mutant>(lines.begin(), half), "mutated-a", tally);
  checkBatch(o, std::vector<Mutant>(half, lines.end()), "mutated-b", tally);
  expectCleanAndVaried(tally, kBatchLines);
  fs::remove_all(o.dir);
}

TEST(Mutation, SolveOfMutatedFilesKeepsEveryInvariant) {
  const std::vector<Mutant> specs = mutants(kSolveCalls, kSeed + 1, MutationOptions());
  const CliOptions o = options("solve");
  Tally tally;
  for (std::size_t i = 0; i < specs.size(); ++i)
    checkSolve(o, specs[i], "spec-" + std::to_string(i), tally);
  expectCleanAndVaried(tally, kSolveCalls);
  fs::remove_all(o.dir);
}

// Inputs the fuzzer and the campaign found, minimised: each must now pass every check, or be a
// failure still listed in known_failures.cpp (RELPOS_FUZZ_STRICT=1 fails on those too).
TEST(Mutation, SavedRegressionsPassOrAreKnown) {
  const CliOptions o = options("saved");
  Tally tally;
  int n = 0;
  for (const auto& e : fs::directory_iterator(RELPOS_FUZZ_REGRESSIONS_DIR))
    if (e.path().extension() != ".md") checkSaved(o, e.path(), tally), ++n;
  EXPECT_GT(n, 0);
  EXPECT_EQ(tally.failures(), 0) << tally.text();
  std::cout << tally.text(0);
  fs::remove_all(o.dir);
}

}  // namespace
}  // namespace relpos::fuzz
