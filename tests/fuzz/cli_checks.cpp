#include "cli_checks.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "known_failures.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/result_writer.hpp"

namespace relpos::fuzz {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void spit(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  return lines;
}

bool startsWith(std::string_view s, std::string_view head) {
  return s.substr(0, head.size()) == head;
}

// A path the CLI quotes unchanged: printable ASCII (it escapes control characters and replaces
// invalid UTF-8 in what it prints).
bool plain(const std::string& s) {
  return std::all_of(s.begin(), s.end(), [](char c) { return c >= 0x20 && c < 0x7F; });
}

struct Ran {
  int code = 0;    // exit status (when neither crashed nor hung)
  int signal = 0;  // the signal that ended it (crashed)
  bool hung = false;
  double seconds = 0;
  std::string out, err;
};

// `relpos ARGS` under `timeout`, stdout and stderr captured in files of the scratch folder.
Ran runRelpos(const CliOptions& o, const std::string& args, const std::string& name,
              int timeout_s) {
  const fs::path out = o.dir / (name + ".out"), err = o.dir / (name + ".err");
  const std::string cmd = "timeout -k 10 " + std::to_string(timeout_s) + " '" + o.exe + "' " +
                          args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const auto t0 = Clock::now();
  const int status = std::system(cmd.c_str());
  Ran r;
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (WIFSIGNALED(status)) {
    r.signal = WTERMSIG(status);
  } else {
    r.code = WEXITSTATUS(status);
    if (r.code == 124 || r.code == 137)
      r.hung = true;  // timeout's TERM, then KILL
    else if (r.code > 128)
      r.signal = r.code - 128;  // the shell's report of a signal
  }
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string tail(const std::string& s, std::size_t n = 600) {
  return printable(s.size() > n ? s.substr(s.size() - n) : s, n);
}

// A process that crashed, hung or exited with a code outside `allowed`.
std::optional<Finding> processFailure(const Ran& r, std::initializer_list<int> allowed,
                                      int timeout_s) {
  if (r.hung) return Finding{"hang", "killed after " + std::to_string(timeout_s) + " s"};
  if (r.signal)
    return Finding{"crash", "signal " + std::to_string(r.signal) + "; stderr: " + tail(r.err)};
  if (r.code == 1) return Finding{"exit-1", "stderr: " + tail(r.err)};
  if (std::find(allowed.begin(), allowed.end(), r.code) == allowed.end())
    return Finding{"exit-code", "exit " + std::to_string(r.code) + "; stderr: " + tail(r.err)};
  return std::nullopt;
}

std::string batchArgs(const CliOptions& o, const fs::path& in, const fs::path& out) {
  return "batch '" + in.string() + "' --jobs " + std::to_string(o.jobs) + " --samples " +
         std::to_string(o.samples) + " --seed " + std::to_string(o.seed) + " -o '" + out.string() +
         "'";
}

std::string joinedLines(const std::vector<Mutant>& lines) {
  std::string text;
  for (const Mutant& m : lines) text += m.text + "\n";
  return text;
}

// Runs the lines as a batch and says only whether the process failed (for bisecting).
std::optional<Finding> batchProcessFailure(const CliOptions& o, const std::vector<Mutant>& lines,
                                           const std::string& name) {
  const fs::path in = o.dir / (name + ".jsonl"), out = o.dir / (name + ".results.jsonl");
  spit(in, joinedLines(lines));
  return processFailure(runRelpos(o, batchArgs(o, in, out), name, o.batch_timeout_s), {0},
                        o.batch_timeout_s);
}

// Halves the lines [from, to) until the ones that make a batch fail on their own are found:
// each is reported, its index added to `culprits`.
void bisect(const CliOptions& o, const std::vector<Mutant>& lines, std::size_t from, std::size_t to,
            const std::string& name, const Finding& failure, Tally& tally,
            std::vector<std::size_t>& culprits) {
  if (to - from == 1) {
    tally.add(failure, lines[from], "batch (one line)");
    culprits.push_back(from);
    return;
  }
  const std::size_t mid = from + (to - from) / 2;
  for (const auto& [a, b] : {std::pair{from, mid}, std::pair{mid, to}}) {
    const std::vector<Mutant> half(lines.begin() + static_cast<std::ptrdiff_t>(a),
                                   lines.begin() + static_cast<std::ptrdiff_t>(b));
    const std::string part = name + "-" + std::to_string(a);
    if (auto f = batchProcessFailure(o, half, part))
      bisect(o, lines, a, b, part, *f, tally, culprits);
  }
}

// One line of a batch's output against the line it answers.
void checkBatchLine(const CliOptions& o, const Mutant& in, const std::string& out,
                    const std::string& source, const std::string& default_name, Tally& tally) {
  const std::string where = "batch " + source;
  Findings f;
  const ParseResult parsed = parseSpec(in.text, builtinRegistry(), default_name);
  checkDiagnostics(parsed, f, false);  // the line's message is a JSON string: any byte is fine
  checkAccepted(in.text, parsed, f);
  if (!isValidUtf8(out)) {
    f.push_back({"bad-output", "the result line is not valid UTF-8: " + printable(out)});
    return tally.addAll(f, in, where);
  }
  const nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("status") || !j["status"].is_string()) {
    f.push_back({"bad-output", "the result line is not a JSON result: " + printable(out)});
    return tally.addAll(f, in, where);
  }
  const std::string status = j["status"].get<std::string>();
  ++tally.statuses[status];
  if (!parsed.problem) {
    if (status != "invalid")
      f.push_back({"exit-code", "an invalid spec's line says '" + status + "'"});
    const std::string message = j.value("message", std::string());
    if (!startsWith(message, source + ": "))
      f.push_back({"pathless-message", "an invalid line's message does not start with '" + source +
                                           ": ': " + printable(message)});
    for (const Diagnostic& d : parsed.errors)
      if (!d.path.empty() && plain(d.path) &&
          message.find(source + ": " + d.path + ": ") == std::string::npos)
        f.push_back({"pathless-message",
                     "the message does not name '" + d.path + "': " + printable(message)});
    if (!j.contains("name") || !j["name"].is_string())
      f.push_back({"bad-output", "an invalid line without a name: " + printable(out)});
  } else {
    if (status == "invalid")
      f.push_back({"exit-code", "a valid spec's line says invalid: " + printable(out)});
    if (status == "unhandled" && startsWith(j.value("message", std::string()), "internal error"))
      f.push_back({"crash", "a worker threw: " + printable(j.value("message", std::string()))});
    if (status != "invalid") {
      ResultExpectation e;
      e.samples = o.samples;
      checkResultText(out, *parsed.problem, e, f);
    }
  }
  tally.addAll(f, in, where);
}

}  // namespace

void Tally::add(const Finding& f, const Mutant& input, const std::string& command) {
  if (const KnownFailure* k = knownFailure(f, input.text)) {
    ++known[k->id];
    return;
  }
  ++findings[f.kind];
  if (reports.size() < keep) reports.push_back({f, input, command});
}

void Tally::addAll(const Findings& fs, const Mutant& input, const std::string& command) {
  for (const Finding& f : fs) add(f, input, command);
}

long Tally::total(const std::string& kind) const {
  const auto it = findings.find(kind);
  return it == findings.end() ? 0 : it->second;
}

long Tally::failures() const {
  long n = 0;
  for (const auto& [kind, count] : findings)
    if (kind != "slow") n += count;
  return n;
}

void Tally::timed(double seconds, const std::string& where, const Mutant& input, double slow_s) {
  if (seconds > slowest_s) slowest_s = seconds, slowest = where;
  if (seconds > slow_s)
    add({"slow", where + " took " + std::to_string(seconds) + " s"}, input, where);
}

void Tally::merge(const Tally& t) {
  batch_lines += t.batch_lines;
  solve_calls += t.solve_calls;
  in_process += t.in_process;
  for (const auto& [k, n] : t.statuses) statuses[k] += n;
  for (const auto& [k, n] : t.findings) findings[k] += n;
  for (const auto& [k, n] : t.known) known[k] += n;
  for (const Report& r : t.reports)
    if (reports.size() < keep) reports.push_back(r);
  if (t.slowest_s > slowest_s) slowest_s = t.slowest_s, slowest = t.slowest;
}

namespace {
// Strings as "LENGTH\nBYTES": any byte survives.
void put(std::ostream& o, const std::string& s) { o << s.size() << '\n' << s; }
std::string get(std::istream& in) {
  std::size_t n = 0;
  in >> n;
  in.get();
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  return s;
}
void putMap(std::ostream& o, const std::map<std::string, long>& m) {
  o << m.size() << '\n';
  for (const auto& [k, n] : m) put(o, k), o << ' ' << n << '\n';
}
std::map<std::string, long> getMap(std::istream& in) {
  std::map<std::string, long> m;
  std::size_t size = 0;
  in >> size;
  for (std::size_t i = 0; i < size; ++i) {
    const std::string k = get(in);
    in >> m[k];
  }
  return m;
}
}  // namespace

void Tally::save(const fs::path& file) const {
  std::ofstream o(file, std::ios::binary);
  o << batch_lines << ' ' << solve_calls << ' ' << in_process << ' ' << slowest_s << '\n';
  put(o, slowest);
  putMap(o, statuses);
  putMap(o, findings);
  putMap(o, known);
  o << reports.size() << '\n';
  for (const Report& r : reports)
    for (const std::string* s : {&r.finding.kind, &r.finding.detail, &r.input.text, &r.input.origin,
                                 &r.input.edits, &r.command})
      put(o, *s);
}

Tally Tally::load(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  Tally t;
  in >> t.batch_lines >> t.solve_calls >> t.in_process >> t.slowest_s;
  t.slowest = get(in);
  t.statuses = getMap(in);
  t.findings = getMap(in);
  t.known = getMap(in);
  std::size_t n = 0;
  in >> n;
  for (std::size_t i = 0; i < n && in; ++i) {
    Report r;
    for (std::string* s : {&r.finding.kind, &r.finding.detail, &r.input.text, &r.input.origin,
                           &r.input.edits, &r.command})
      *s = get(in);
    t.reports.push_back(std::move(r));
  }
  return t;
}

std::string Tally::text(std::size_t max_reports) const {
  std::ostringstream s;
  s << "batch lines " << batch_lines << ", solve calls " << solve_calls << ", in-process "
    << in_process << "\nstatuses:";
  for (const auto& [k, n] : statuses) s << " " << k << " " << n;
  s << "\nfindings:";
  static const std::vector<std::string> kinds = {"crash",
                                                 "hang",
                                                 "wrong-answer",
                                                 "exit-1",
                                                 "split-message",
                                                 "pathless-message",
                                                 "split-diagnostic",
                                                 "bad-output",
                                                 "exit-code",
                                                 "lost-line",
                                                 "slow"};
  for (const std::string& k : kinds) s << " " << k << " " << total(k);
  for (const auto& [k, n] : findings)  // any other kind
    if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) s << " " << k << " " << n;
  if (!known.empty()) s << "\nknown failures (not counted; RELPOS_FUZZ_STRICT=1 counts them):";
  for (const auto& [k, n] : known) s << " " << k << " " << n;
  s << "\nslowest: " << slowest_s << " s (" << printable(slowest) << ")\n";
  for (std::size_t i = 0; i < reports.size() && i < max_reports; ++i) {
    const Report& r = reports[i];
    s << "[" << r.finding.kind << "] " << r.command << ": " << r.finding.detail << "\n  from "
      << r.input.origin << " by: " << printable(r.input.edits, 400)
      << "\n  input: " << printable(r.input.text, 1500) << "\n";
  }
  return s.str();
}

// One batch over the lines, its output checked; the process failure when it failed so.
std::optional<Finding> checkBatchOnce(const CliOptions& o, const std::vector<Mutant>& lines,
                                      const std::string& name, Tally& tally);

bool checkBatch(const CliOptions& o, const std::vector<Mutant>& lines, const std::string& name,
                Tally& tally, std::vector<Mutant>* checked) {
  tally.batch_lines += static_cast<long>(lines.size());
  std::vector<Mutant> rest = lines;
  for (;;) {
    if (rest.empty()) break;
    const std::optional<Finding> failure = checkBatchOnce(o, rest, name, tally);
    if (!failure) break;
    std::vector<std::size_t> culprits;
    bisect(o, rest, 0, rest.size(), name, *failure, tally, culprits);
    if (culprits.empty()) {  // only together: reported with the first line as its input
      Finding f = *failure;
      f.detail += " (only with all " + std::to_string(rest.size()) + " lines of this batch)";
      tally.add(f, rest[0], "batch");
      if (checked) checked->clear();
      return false;
    }
    // The others are checked again without the lines that take the batch down.
    for (std::size_t k = culprits.size(); k-- > 0;)
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(culprits[k]));
  }
  if (checked) *checked = rest;
  return rest.size() == lines.size();
}

std::optional<Finding> checkBatchOnce(const CliOptions& o, const std::vector<Mutant>& lines,
                                      const std::string& name, Tally& tally) {
  const fs::path in = o.dir / (name + ".jsonl"), out = o.dir / (name + ".results.jsonl");
  spit(in, joinedLines(lines));
  fs::remove(out);
  const Ran r = runRelpos(o, batchArgs(o, in, out), name, o.batch_timeout_s);
  if (auto failure = processFailure(r, {0}, o.batch_timeout_s)) return failure;
  // stderr: the summary ("batch: …" and its indented lines); anything else names the file.
  for (const std::string& line : linesOf(r.err))
    if (!startsWith(line, "batch: ") && !startsWith(line, "  ") && !startsWith(line, in.string()))
      tally.add({"pathless-message", "batch stderr: " + printable(line)}, lines[0],
                "batch " + in.string());
  const std::vector<std::string> results = linesOf(slurp(out));
  if (results.size() != lines.size())
    tally.add({"lost-line", std::to_string(lines.size()) + " lines in, " +
                                std::to_string(results.size()) + " result lines out"},
              lines[std::min(results.size(), lines.size() - 1)], "batch " + in.string());
  for (std::size_t i = 0; i < results.size() && i < lines.size(); ++i) {
    const std::string n = std::to_string(i + 1);
    checkBatchLine(o, lines[i], results[i], in.string() + ":" + n, name + ":" + n, tally);
  }
  return std::nullopt;
}

double checkSolve(const CliOptions& o, const Mutant& spec, const std::string& name, Tally& tally) {
  const fs::path file = o.dir / (name + ".json");
  spit(file, spec.text);
  ++tally.solve_calls;
  const std::string where = "solve " + file.string();
  const Ran r = runRelpos(o,
                          "solve '" + file.string() + "' --samples " + std::to_string(o.samples) +
                              " --seed " + std::to_string(o.seed),
                          name, o.solve_timeout_s);
  tally.timed(r.seconds, where, spec, o.slow_s);
  if (auto failure = processFailure(r, {0, 2}, o.solve_timeout_s)) {
    tally.add(*failure, spec, where);
    return r.seconds;
  }
  Findings f;
  const ParseResult parsed = parseSpec(spec.text, builtinRegistry(), name);
  checkDiagnostics(parsed, f, false);  // stderr's lines are checked below
  checkAccepted(spec.text, parsed, f);
  const std::vector<std::string> err = linesOf(r.err);
  const std::string head = file.string() + ": ";
  for (const std::string& line : err)
    if (!startsWith(line, head) || line.size() == head.size())
      f.push_back(
          {"split-message", "a stderr line that does not name the file: " + printable(line)});
  if (err.size() != parsed.errors.size() + parsed.warnings.size())
    f.push_back({"split-message", std::to_string(parsed.errors.size() + parsed.warnings.size()) +
                                      " diagnostics on " + std::to_string(err.size()) +
                                      " stderr lines: " + printable(r.err)});
  if (!parsed.problem) {
    ++tally.statuses["invalid"];
    if (r.code != 2)
      f.push_back({"exit-code", "exit " + std::to_string(r.code) + " for an invalid spec"});
    if (!r.out.empty()) f.push_back({"bad-output", "an invalid spec wrote a result"});
    for (const Diagnostic& d : parsed.errors)
      if (!d.path.empty() && plain(d.path) && r.err.find(head + d.path + ": ") == std::string::npos)
        f.push_back(
            {"pathless-message", "stderr does not name '" + d.path + "': " + printable(r.err)});
  } else if (r.code != 0) {
    f.push_back(
        {"exit-code", "exit " + std::to_string(r.code) + " for a valid spec: " + tail(r.err)});
  } else {
    const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
    if (!j.is_discarded() && j.is_object() && j.contains("status") && j["status"].is_string())
      ++tally.statuses[j["status"].get<std::string>()];
    ResultExpectation e;
    e.samples = o.samples;
    e.one_line = false;
    checkResultText(r.out, *parsed.problem, e, f);
  }
  tally.addAll(f, spec, where);
  return r.seconds;
}

double checkInProcess(const Mutant& spec, int samples, std::uint64_t seed, Tally& tally) {
  static thread_local Workspace ws;
  static thread_local Solution sol;
  static thread_local std::string line;
  ++tally.in_process;
  const auto t0 = Clock::now();
  const ParseResult parsed = parseSpec(spec.text, builtinRegistry(), "in-process");
  if (parsed.problem) {
    solve(*parsed.problem, builtinRegistry(), SolverOptions(), ws, sol);
    ResultOptions options;
    options.samples = samples;
    options.seed = seed;
    writeResultLine(*parsed.problem, sol, options, line);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  Findings f;
  checkDiagnostics(parsed, f);
  checkAccepted(spec.text, parsed, f);
  if (parsed.problem) {
    ResultExpectation e;
    e.samples = samples;
    checkResultText(line, *parsed.problem, e, f);
  }
  tally.addAll(f, spec, "in-process");
  return seconds;
}

void checkSaved(const CliOptions& o, const fs::path& file, Tally& tally) {
  Mutant m;
  m.text = slurp(file);
  m.origin = file.string();
  m.edits = "(saved)";
  const std::string name = file.stem().string();
  checkSolve(o, m, name, tally);
  if (m.text.find('\n') == std::string::npos &&
      m.text.find_first_not_of(" \t\r") != std::string::npos)
    checkBatch(o, {m}, name, tally);
  checkInProcess(m, o.samples, o.seed, tally);
}

}  // namespace relpos::fuzz
