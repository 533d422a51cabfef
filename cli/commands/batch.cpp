// relpos batch (docs/spec.md §3): many specs, one result line each, in input order whatever the
// thread count. Workers parse and solve; the main thread writes finished lines in order as soon
// as they are next, draws the progress bar, and prints the summary.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "file_text.hpp"
#include "output_file.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/result_writer.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/text.hpp"

namespace relpos::cli {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) { g_interrupted.store(true); }

// One spec of the batch: a file of a folder, or a line of the JSONL file (a view into its text).
struct Item {
  std::string file;       // a folder's spec file; empty for a JSONL line
  std::string_view text;  // the JSONL line
  std::size_t line = 0;   // its number (1-based)
};

// The batch's input: the folder's spec files, or the JSONL file read once, its lines as views.
// What only some specs need (a line's "FILE:LINE", its default name, the mesh folder) is spelled
// out by the worker that needs it.
struct Input {
  std::string path, dir, stem;     // the JSONL file, its folder and stem
  std::unique_ptr<FileText> text;  // its contents
  std::vector<Item> items;

  // The file, or "FILE.jsonl:LINE".
  std::string source(const Item& i) const {
    return i.file.empty() ? path + ":" + std::to_string(i.line) : i.file;
  }
  // The default name: the file's stem, or "STEM:LINE".
  std::string defaultName(const Item& i) const {
    return i.file.empty() ? stem + ":" + std::to_string(i.line) : fs::path(i.file).stem().string();
  }
  // What relative mesh paths are relative to.
  std::string meshDir(const Item& i) const {
    return i.file.empty() ? dir : fs::path(i.file).parent_path().string();
  }
};

struct Outcome {
  std::string name, status;
  std::vector<int> dofs;
  double solve_us = 0.0, total_us = 0.0;
};

// The specs of a folder (*.json in name order; other files are not specs) or of a JSONL file
// (one spec per non-blank line).
void collectItems(const std::string& path, Input* input) {
  if (fs::is_directory(path)) {
    for (const auto& f : specFiles({path})) input->items.push_back({f, {}, 0});
    return;
  }
  input->text = std::make_unique<FileText>(path);
  input->path = path;
  input->dir = fs::path(path).parent_path().string();
  input->stem = fs::path(path).stem().string();
  const std::string_view text = input->text->view();
  std::size_t n = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string_view line = text.substr(at, end - at);
    ++n;
    if (line.find_first_not_of(" \t\r") != std::string_view::npos)
      input->items.push_back({std::string(), line, n});
    at = end + 1;
  }
}

// "SOURCE: json.path: what" for every problem, joined by "; ".
std::string joined(const std::string& source, const std::vector<Diagnostic>& problems) {
  std::string message;
  for (const auto& e : problems)
    message += (message.empty() ? "" : "; ") + formatDiagnostic(source, e);
  return message;
}

// An invalid spec's "name" when it has a readable one, else the file's stem or "STEM:LINE".
// (The parse has it already: the text is not read a second time.)
const std::string& specName(const ParseResult& parsed) { return parsed.name; }

// The worker's reusable state: the solver's workspace and solution, and the line being written
// (a buffer that has grown to a line's size once).
struct WorkerState {
  Workspace ws;
  Solution sol;
  Report report;
  std::string line;  // its result line
  std::string name;  // the spec's name once it is known (for a line about a failure)
};

// Parses and solves one spec: its result line into state.line (every problem of an invalid spec
// joined into its message, "SOURCE: json.path: what"), the rest for the summary.
Outcome run(const Input& input, const Item& item, const Args& a, const Registry& reg,
            collision::MeshCache& cache, WorkerState& state) {
  Solution& sol = state.sol;
  const auto t0 = Clock::now();
  Outcome out;
  state.name.clear();
  ParseResult parsed;
  if (!item.file.empty()) {
    parsed = parseSpecFile(item.file, reg);
  } else {
    parsed = parseSpec(item.text, reg, input.defaultName(item));
  }
  if (!parsed.problem) {
    out.name = specName(parsed);
    out.status = "invalid";
    writeStatusLine(out.name, "invalid", joined(input.source(item), parsed.errors), state.line);
  } else {
    const Problem& pb = *parsed.problem;
    state.name = pb.name;
    solve(pb, reg, SolverOptions(), state.ws, sol);
    out.name = pb.name;
    out.status = toString(sol.status);
    if (!a.collision) {
      evaluate(pb, sol, a.result, state.report);
      ResultFormat line = kResultLine;
      line.degrees = a.degrees;
      writeReport(state.report, line, state.line);
    } else {
      std::vector<Diagnostic> errors, warnings;
      if (const auto scene =
              collision::buildScene(pb, input.meshDir(item), cache, &errors, &warnings)) {
        evaluate(pb, sol, a.result, state.report, scene.get());
        ResultFormat line = kCollisionLine;
        line.degrees = a.degrees;
        writeReport(state.report, line, state.line);
        out.status = toString(state.report.status);
      } else {
        writeStatusLine(pb.name, "invalid", joined(input.source(item), errors), state.line);
        out.status = "invalid";
      }
    }
    if (out.status != "invalid")
      for (const auto& b : sol.branches) out.dofs.push_back(b.manifold->dof());
    out.solve_us = sol.solve_us;
  }
  out.total_us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  return out;
}

// run(), with whatever it throws turned into the spec's result line ("unhandled", the reason):
// nothing one spec does (a plugin that throws, a library that fails) may take down the batch and
// the lines other specs finished.
Outcome runGuarded(const Input& input, const Item& item, const Args& a, const Registry& reg,
                   collision::MeshCache& cache, std::unique_ptr<WorkerState>& state) {
  std::string what;
  try {
    return run(input, item, a, reg, cache, *state);
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "an exception that is not a std::exception";
  }
  Outcome out;
  out.name = state->name.empty() ? input.defaultName(item) : state->name;
  out.status = "unhandled";
  // The solver's buffers may be half-way through a solve: the next spec starts from fresh ones.
  state = std::make_unique<WorkerState>();
  writeStatusLine(out.name, "unhandled", "internal error: " + what, state->line);
  return out;
}

void drawProgress(std::size_t done, std::size_t total, double seconds) {
  const int width = 30;
  const double f = total ? static_cast<double>(done) / total : 1.0;
  const double rate = seconds > 0 ? done / seconds : 0.0;
  const double eta = rate > 0 ? (total - done) / rate : 0.0;
  std::string bar(static_cast<std::size_t>(f * width), '#');
  bar.resize(width, '.');
  std::fprintf(stderr, "\r[%s] %zu/%zu  %.0f specs/s  ETA %.1f s ", bar.c_str(), done, total, rate,
               eta);
  std::fflush(stderr);
}

void printSummary(const std::vector<Outcome>& outcomes, std::size_t written, double seconds,
                  int jobs, bool interrupted) {
  std::map<std::string, int> by_status;
  std::map<int, int> dof_histogram;
  std::vector<double> solve_us, total_us;
  for (std::size_t i = 0; i < written; ++i) {
    const Outcome& o = outcomes[i];
    ++by_status[o.status];
    for (int d : o.dofs) ++dof_histogram[d];
    if (o.status != "invalid") solve_us.push_back(o.solve_us);
    total_us.push_back(o.total_us);
  }
  auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  std::ostringstream s;
  s << "batch: " << written << (interrupted ? " specs before the interruption" : " specs") << " in "
    << seconds << " s (" << static_cast<long>(seconds > 0 ? written / seconds : 0.0) << " specs/s, "
    << jobs << (jobs == 1 ? " thread)\n" : " threads)\n");
  s << "  status:";
  for (const auto& [status, n] : by_status) s << " " << status << " " << n;
  s << "\n  branch DOF:";
  for (const auto& [dof, n] : dof_histogram) s << " " << dof << ":" << n;
  s << "\n  per spec: median " << median(total_us) << " us parse+solve+write (thread time), "
    << "median solve " << median(solve_us) << " us\n";
  std::vector<std::size_t> order(written);
  for (std::size_t i = 0; i < written; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return outcomes[x].solve_us > outcomes[y].solve_us;
  });
  s << "  slowest solves:";
  for (std::size_t k = 0; k < std::min<std::size_t>(5, order.size()); ++k)
    s << " " << oneLine(outcomes[order[k]].name) << " (" << outcomes[order[k]].solve_us << " us)";
  s << "\n";
  std::cerr << s.str();
}

}  // namespace

int cmdBatch(const Args& a, const Registry& reg) {
  if (a.positional.size() != 1) throw UsageError("batch takes one folder or one JSONL file");
  requireCollisionForItsOptions(a);
  Input input;
  collectItems(a.positional[0], &input);
  const std::vector<Item>& items = input.items;
  const int jobs = a.jobs > 0 ? a.jobs : std::max(1u, std::thread::hardware_concurrency());

  // -o is checked against the inputs before anything is opened for writing: truncating the
  // JSONL file this batch has mapped would destroy the input (and kill the batch with SIGBUS).
  std::unique_ptr<LineSink> sink;
  if (a.out.empty()) {
    sink = std::make_unique<LineSink>();
  } else {
    std::vector<std::string> inputs;
    if (input.path.empty())
      for (const auto& item : items) inputs.push_back(item.file);
    else
      inputs.push_back(input.path);
    checkOutput(a.out, inputs, OutputMode::kStream);
    sink = std::make_unique<LineSink>(a.out);
  }
  // The bar goes to stderr, on a terminal, unless the result lines go to that terminal too.
  const bool progress = isatty(STDERR_FILENO) && !(a.out.empty() && isatty(STDOUT_FILENO));

  g_interrupted.store(false);
  auto previous = std::signal(SIGINT, onInterrupt);
  std::atomic<bool> write_failed{false};  // the output refused a write: no point going on
  const auto stopping = [&] { return g_interrupted.load() || write_failed.load(); };

  std::vector<Outcome> outcomes(items.size());
  std::unique_ptr<std::atomic<bool>[]> done(new std::atomic<bool>[items.size()]);
  for (std::size_t i = 0; i < items.size(); ++i) done[i].store(false);
  std::atomic<std::size_t> next_item{0};
  // Finished lines wait in a ring of reusable buffers: line i in slot i % kSlots, once line
  // i − kSlots is written. The buffers keep their capacity, so after the first lap no line is
  // allocated or freed; a writer freeing what workers allocated made both wait on glibc's arena
  // locks. A worker more than kSlots lines ahead of the writer waits for it.
  constexpr std::size_t kSlots = 4096;
  std::vector<std::string> slots(std::min(kSlots, items.size()));
  std::atomic<std::size_t> written{0};
  collision::MeshCache cache;
  auto worker = [&] {
    auto state = std::make_unique<WorkerState>();
    for (;;) {
      if (stopping()) return;
      const std::size_t i = next_item.fetch_add(1);
      if (i >= items.size()) return;
      outcomes[i] = runGuarded(input, items[i], a, reg, cache, state);
      while (i >= written.load(std::memory_order_acquire) + kSlots) {
        if (stopping()) return;
        std::this_thread::sleep_for(std::chrono::microseconds(100));
      }
      slots[i % kSlots].assign(state->line);
      done[i].store(true, std::memory_order_release);
    }
  };
  const auto t0 = Clock::now();
  std::vector<std::thread> threads;
  for (int k = 0; k < jobs; ++k) threads.emplace_back(worker);

  // Write in order: line i as soon as lines 0..i are finished.
  auto last_draw = Clock::now();
  // Lines go out in chunks of about 1 MB: one system call per line, at 100,000 lines a second,
  // was a tenth of a core taken from the workers. Each chunk holds whole lines, so the end of
  // the last chunk written is the end of a complete line.
  std::string pending;
  std::size_t pending_lines = 0;
  auto writePending = [&] {
    if (!pending.empty() && !write_failed.load() && !sink->write(pending, pending_lines))
      write_failed.store(true);
    pending.clear();
    pending_lines = 0;
  };
  auto writeReady = [&] {
    std::size_t w = written.load();
    while (w < items.size() && done[w].load(std::memory_order_acquire) && !write_failed.load()) {
      pending += slots[w % kSlots];
      pending += '\n';
      ++pending_lines;
      written.store(++w, std::memory_order_release);
      if (pending.size() >= (std::size_t{1} << 20)) writePending();
    }
  };
  while (written.load() < items.size() && !stopping()) {
    writeReady();
    if (progress && Clock::now() - last_draw > std::chrono::milliseconds(100)) {
      drawProgress(written.load(), items.size(),
                   std::chrono::duration<double>(Clock::now() - t0).count());
      last_draw = Clock::now();
    }
    if (written.load() < items.size()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  for (auto& t : threads) t.join();
  writeReady();  // after an interruption: every line finished before it, still in order
  writePending();
  const bool closed = sink->close();
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (progress) {
    drawProgress(written.load(), items.size(), seconds);
    std::fputc('\n', stderr);
  }
  std::signal(SIGINT, previous);
  if (write_failed.load() || !closed) throw WriteFailed(sink->error());
  const bool interrupted = written.load() < items.size();
  printSummary(outcomes, written.load(), seconds, jobs, interrupted);
  return interrupted ? kExitInterrupted : kExitOk;
}

}  // namespace relpos::cli
