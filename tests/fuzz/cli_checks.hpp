#pragma once
// Mutated specs through the CLI's code path: the real `relpos` executable, `batch` on a JSONL
// file of many mutated lines (one process for thousands of specs) and `solve FILE`, every
// output checked against the specs as relpos::parseSpec reads them (result_checks.hpp) — the
// shared part of the mutation test and the mutation campaign.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "result_checks.hpp"

namespace relpos::fuzz {

struct Mutant {
  std::string text;    // the spec (one line for batch)
  std::string origin;  // the data/ spec it came from
  std::string edits;   // the mutations applied
};

struct CliOptions {
  std::string exe;            // the relpos executable
  std::filesystem::path dir;  // a scratch folder of this run's own
  int samples = 3;            // --samples
  std::uint64_t seed = 7;     // --seed
  int jobs = 2;               // batch --jobs
  int batch_timeout_s = 600;  // a batch killed after this is a hang
  int solve_timeout_s = 60;   // a solve killed after this is a hang
  double slow_s = 1.0;        // a spec slower than this is "slow" (reported, not asserted)
};

// One finding with the input that caused it.
struct Report {
  Finding finding;
  Mutant input;
  std::string command;  // how it was run ("batch FILE.jsonl:LINE", "solve FILE", "in-process")
};

// What a run saw: how many specs, their statuses, findings by kind (the first reports in full).
struct Tally {
  long batch_lines = 0, solve_calls = 0, in_process = 0;
  std::map<std::string, long> statuses;  // solved, inconsistent, unhandled, invalid
  std::map<std::string, long> findings;  // kind -> count (known failures not included)
  std::map<std::string, long> known;     // known failure id -> count (known_failures.hpp)
  std::vector<Report> reports;           // the first `keep` findings in full
  std::size_t keep = 50;
  double slowest_s = 0.0;
  std::string slowest;  // where the slowest spec was run

  void add(const Finding& f, const Mutant& input, const std::string& command);
  void addAll(const Findings& fs, const Mutant& input, const std::string& command);
  long total(const std::string& kind) const;
  long failures() const;  // every finding except "slow"
  // A summary and the kept reports, one per line (inputs quoted printable).
  std::string text(std::size_t max_reports = 20) const;
  void timed(double seconds, const std::string& where, const Mutant& input, double slow_s);
  // Adds another tally's counts and reports (the campaign runs chunks in child processes).
  void merge(const Tally& other);
  // Byte-exact text form (inputs may hold any byte), for a child process to hand back.
  void save(const std::filesystem::path& file) const;
  static Tally load(const std::filesystem::path& file);
};

// `relpos batch` over `lines` written as one JSONL file (`name`.jsonl in opts.dir). When the
// process crashes, hangs or exits 1, the lines are bisected with further batches until the
// lines that do it alone are found; those are reported and the others run again without them.
// `checked` (optional) receives the lines whose results were checked; true when all were.
bool checkBatch(const CliOptions& opts, const std::vector<Mutant>& lines, const std::string& name,
                Tally& tally, std::vector<Mutant>* checked = nullptr);

// `relpos solve FILE` (`name`.json in opts.dir) for one spec; returns its wall time in seconds.
double checkSolve(const CliOptions& opts, const Mutant& spec, const std::string& name,
                  Tally& tally);

// parseSpec, solve and writeResultLine in this process, as a batch worker runs them, with the
// result read back and checked; returns the seconds it took.
double checkInProcess(const Mutant& spec, int samples, std::uint64_t seed, Tally& tally);

// A saved input (tests/fuzz/regressions/) through every path above: solve, batch (as a line,
// when it holds no newline) and in-process.
void checkSaved(const CliOptions& opts, const std::filesystem::path& file, Tally& tally);

}  // namespace relpos::fuzz
