// The relpos command (SPEC.md §3): solve, rules, table.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "file_text.hpp"
#include "output_file.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/collision/branch_filter.hpp"
#include "relpos/core/plugin_api.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/result_writer.hpp"
#include "relpos/plugins/loader.hpp"
#include "safe_text.hpp"

namespace fs = std::filesystem;
using relpos::Registry;

namespace relpos::cli {

double parseNonNegative(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end || !(x >= 0) || !std::isfinite(x))
    throw UsageError(flag + ": expected a non-negative number, got '" + v + "'");
  return x;
}

long parseInt(const std::string& flag, const std::string& v, long lo, long hi) {
  char* end = nullptr;
  long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end || x < lo || x > hi)
    throw UsageError(flag + ": expected an integer in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got '" + v + "'");
  return x;
}

Args parseArgs(int argc, char** argv, int first) {
  Args a;
  for (int i = first; i < argc; ++i) {
    std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(s + ": missing value");
      return argv[++i];
    };
    if (s == "--samples")
      a.result.samples = static_cast<int>(parseInt(s, value(), 0, 1000000));
    else if (s == "--seed")
      a.result.seed = static_cast<std::uint64_t>(parseInt(s, value(), 0, LONG_MAX));
    else if (s == "--repeat")
      a.repeat = static_cast<int>(parseInt(s, value(), 1, 1000000));
    else if (s == "--window")
      a.result.window = parseNonNegative(s, value());
    else if (s == "--collision")
      a.collision = true;
    else if (s == "--clearance")
      a.filter.clearance = parseNonNegative(s, value()), a.collision_option = true;
    else if (s == "--collision-samples")
      a.filter.samples = static_cast<int>(parseInt(s, value(), 0, 1000000)),
      a.collision_option = true;
    else if (s == "-o")
      a.out = value(), a.out_given = true;
    else if (s == "--coverage")
      a.coverage = true;
    else if (s == "--plugin")
      a.plugins.push_back(value());
    else if (s == "--jobs")
      a.jobs = static_cast<int>(parseInt(s, value(), 1, 1024));
    else if (s == "--allow-override")
      a.allow_override = true;
    else if (s.size() > 1 && s[0] == '-')
      throw UsageError("unknown option '" + s + "'");
    else
      a.positional.push_back(s);
  }
  return a;
}

// Diagnostics go to stderr one per line, whatever the names they quote hold (a newline, 0xFF).
void printDiagnostics(const std::string& file, const std::vector<relpos::Diagnostic>& errors,
                      const std::vector<relpos::Diagnostic>& warnings) {
  for (const auto& w : warnings)
    std::cerr << oneLine(relpos::formatDiagnostic(file, w)) << " (warning)\n";
  for (const auto& e : errors) std::cerr << oneLine(relpos::formatDiagnostic(file, e)) << "\n";
}

bool loadProblem(const std::string& file, const Registry& reg, relpos::Problem* pb) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) {  // opening it succeeds, reading it fails: say what it is
    std::cerr << oneLine(file + ": is a directory, not a spec file") << "\n";
    return false;
  }
  relpos::ParseResult r = relpos::parseSpecFile(file, reg);
  printDiagnostics(file, r.errors, r.warnings);
  if (!r.problem) return false;
  *pb = std::move(*r.problem);
  return true;
}

nlohmann::ordered_json resultTree(const relpos::Problem& pb, const relpos::Solution& sol,
                                  const relpos::ResultOptions& options) {
  std::string line;
  relpos::writeResultLine(pb, sol, options, line);
  return nlohmann::ordered_json::parse(line);  // the writer writes UTF-8 whatever names hold
}

bool collisionFields(const std::string& spec_dir, const Args& a, const relpos::Problem& pb,
                     const relpos::Solution& sol, relpos::collision::MeshCache& cache,
                     nlohmann::ordered_json* result, std::vector<relpos::Diagnostic>* errors,
                     std::vector<relpos::Diagnostic>* warnings) {
  auto scene = relpos::collision::buildScene(pb, spec_dir, cache, errors, warnings);
  if (!scene) return false;
  relpos::collision::FilterOptions options = a.filter;
  options.window = a.result.window;
  options.seed = a.result.seed;
  int free_branches = 0;
  for (std::size_t b = 0; b < sol.branches.size(); ++b) {
    const relpos::Branch& branch = sol.branches[b];
    // The nearest pose resultToJson already searched for (its parameters are stored as doubles,
    // so the pose is rebuilt exactly instead of searching again).
    const auto& near = (*result)["branches"][b]["nearest"];
    relpos::NearestPose n;
    for (int i = 0; i < branch.manifold->dof(); ++i)
      n.parameters[i] = near["parameters"][i].get<double>();
    n.pose = branch.manifold->pose(n.parameters);
    n.distance = near["distance"].get<double>();
    const auto c = relpos::collision::filterBranch(*scene, branch, n, pb.mobile.pose, options);
    free_branches += c.has_nearest_free || !c.free_samples.empty();
    (*result)["branches"][b]["collision"] = relpos::collision::collisionToJson(
        c, branch.manifold->dof(), scene->checkedAgainst(), options.clearance);
  }
  (*result)["collision_free_branches"] = free_branches;
  return true;
}

// The collision fields of a spec file, its meshes' problems reported on stderr.
bool addCollisionFields(const std::string& file, const Args& a, const relpos::Problem& pb,
                        const relpos::Solution& sol, nlohmann::ordered_json* result) {
  relpos::collision::MeshCache cache;
  std::vector<relpos::Diagnostic> errors, warnings;
  const bool ok = collisionFields(fs::path(file).parent_path().string(), a, pb, sol, cache, result,
                                  &errors, &warnings);
  printDiagnostics(file, errors, warnings);
  return ok;
}

int cmdSolve(const Args& a, const Registry& reg) {
  if (a.positional.size() != 1) throw UsageError("solve takes exactly one spec file");
  if (a.collision_option && !a.collision)
    throw UsageError("--clearance and --collision-samples need --collision");
  // Before solving: an -o that cannot be written is known now, not after the work.
  if (!a.out.empty()) checkOutput(a.out, a.positional, OutputMode::kReplace);
  relpos::Problem pb;
  if (!loadProblem(a.positional[0], reg, &pb)) return kExitInvalid;
  relpos::Workspace ws;
  relpos::Solution sol;
  relpos::solve(pb, reg, relpos::SolverOptions(), ws, sol);
  nlohmann::ordered_json result = resultTree(pb, sol, a.result);
  if (a.collision) {
    try {
      if (!addCollisionFields(a.positional[0], a, pb, sol, &result)) return kExitInvalid;
    } catch (const std::exception& e) {
      // The filter samples the branches: a plugin's manifold that throws there is an answer
      // naming the plugin, not exit 1 (the writer guards itself the same way).
      result = resultTree(pb, relpos::unhandledAfterThrow(sol, "filtering collisions", e.what()),
                          a.result);
      result["collision_free_branches"] = 0;
    }
  }
  // Strings from the input (a default name from a file name holding 0xFF) may not be UTF-8:
  // replaced, where the default handler would throw.
  const std::string text =
      result.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  if (!a.out.empty()) {
    replaceFile(a.out, text);
    return kExitOk;
  }
  std::cout << text << std::flush;
  if (!std::cout) throw WriteFailed("standard output: cannot write the result");
  return kExitOk;
}

// How often each rule case fired over a folder of specs, and which never fired.
int cmdRuleCoverage(const Args& a, const Registry& reg) {
  if (a.positional.empty()) throw UsageError("rules --coverage needs a folder or spec files");
  std::map<std::string, int> count;
  for (const auto& r : reg.rules()) {
    if (r.cases.empty()) count[r.name] = 0;
    for (const auto& c : r.cases) count[c.name] = 0;
  }
  relpos::Workspace ws;
  relpos::Solution sol;
  int invalid = 0, specs = 0;
  for (const auto& f : specFiles(a.positional)) {
    relpos::Problem pb;
    if (!loadProblem(f, reg, &pb)) {
      ++invalid;
      continue;
    }
    ++specs;
    relpos::solve(pb, reg, relpos::SolverOptions(), ws, sol);
    for (const char* name : sol.ruleNames()) ++count[name];
  }
  int never = 0;
  for (const auto& r : reg.rules()) {
    auto row = [&](const std::string& name, const std::string& citation) {
      std::printf("%6d  %-36s %s\n", count[name], name.c_str(), citation.c_str());
      never += count[name] == 0;
    };
    if (r.cases.empty()) row(r.name, r.citation);
    for (const auto& c : r.cases) row(c.name, c.citation);
  }
  std::printf("%d specs solved, %d invalid; %d rule cases never fired", specs, invalid, never);
  if (never) {
    std::printf(":");
    for (const auto& [name, n] : count)
      if (n == 0) std::printf(" %s", name.c_str());
  }
  std::printf("\n");
  return invalid ? kExitInvalid : kExitOk;
}

int cmdRules(const Args& a, const Registry& reg) {
  if (a.coverage) return cmdRuleCoverage(a, reg);
  if (!a.positional.empty()) throw UsageError("rules takes no arguments (or --coverage DIR)");
  std::cout << "constraint types:\n";
  for (const auto& t : reg.constraintTypes()) {
    std::cout << "  " << t.name << "  [" << t.origin << "]  " << t.description << "\n    accepts:";
    for (const auto& p : t.accepts)
      std::cout << " " << relpos::toString(p.fixed) << "-" << relpos::toString(p.mobile);
    std::cout << "\n";
  }
  std::cout << "combination rules:\n";
  for (const auto& r : reg.rules()) {
    std::cout << "  " << r.name << "  (" << relpos::toString(r.first) << " + "
              << relpos::toString(r.second) << ")  [" << r.origin << "]  " << r.citation << "\n";
    for (const auto& c : r.cases) std::cout << "    " << c.name << "  " << c.citation << "\n";
  }
  std::cout << "manifolds:\n";
  for (const auto& m : reg.manifolds())
    std::cout << "  " << m.name << "  [" << m.origin << "]  " << m.description << "\n";
  std::cout << "matchers:\n";
  for (const auto& m : reg.matchers()) std::cout << "  " << m.name << "  [" << m.origin << "]\n";
  if (!reg.customKinds().empty()) {
    std::cout << "custom fundamental kinds:\n";
    for (const auto& k : reg.customKinds())
      std::cout << "  " << k.name << "  [" << k.origin << "]  " << k.description << "\n";
  }
  return kExitOk;
}

// Loads, in order, the plugins of RELPOS_PLUGIN_PATH, of --plugin, and of the "plugins" lists of
// the specs the command will read. The first failure is one line on stderr; false then.
bool loadPlugins(const std::string& cmd, const Args& a, Registry& reg) {
  struct Item {
    std::string path, where;  // where: what named it, for the message
  };
  std::vector<Item> items;
  if (const char* env = std::getenv("RELPOS_PLUGIN_PATH"))
    for (const auto& p : relpos::plugins::expandPluginPath(env))
      items.push_back({p, "RELPOS_PLUGIN_PATH: "});
  for (const auto& p : a.plugins) items.push_back({p, ""});
  std::vector<std::string> specs;
  if (cmd == "solve" && a.positional.size() == 1) specs = a.positional;
  const bool batch = cmd == "batch" && a.positional.size() == 1;
  if ((cmd == "table" || (cmd == "rules" && a.coverage) ||
       (batch && fs::is_directory(a.positional[0]))) &&
      !a.positional.empty())
    specs = specFiles(a.positional);
  else if (batch && fs::is_regular_file(a.positional[0])) {
    // A JSONL file: each line's list, relative to the file's folder. One search of the whole
    // text first: most batches name no plugin, and then no line needs looking at.
    // The lines are views into the mapped text (as the batch reads them), numbered alike.
    const FileText text(a.positional[0]);
    const std::string dir = fs::path(a.positional[0]).parent_path().string();
    const std::string_view all =
        relpos::mentionsPlugins(text.view()) ? text.view() : std::string_view();
    std::size_t n = 0;
    for (std::size_t at = 0; at < all.size(); ++n) {
      const std::size_t end = std::min(all.find('\n', at), all.size());
      const auto paths = relpos::specPluginPathsInText(all.substr(at, end - at), dir);
      for (std::size_t i = 0; i < paths.size(); ++i)  // "FILE:LINE: plugins[i]: ", one line
        items.push_back(
            {paths[i], relpos::formatDiagnostic(a.positional[0] + ":" + std::to_string(n + 1),
                                                {"plugins[" + std::to_string(i) + "]", ""})});
      at = end + 1;
    }
  }
  for (const auto& spec : specs) {
    const auto paths = relpos::specPluginPaths(spec);
    for (std::size_t i = 0; i < paths.size(); ++i)
      items.push_back({paths[i], spec + ": plugins[" + std::to_string(i) + "]: "});
  }
  relpos::plugins::LoadOptions options;
  options.allow_override = a.allow_override;
  for (const auto& item : items) {
    std::string error;
    if (!relpos::plugins::loadPlugin(item.path, reg, &error, options)) {
      std::cerr << "relpos: " << oneLine(item.where + error) << "\n";
      return false;
    }
  }
  return true;
}

std::string readAll(std::istream& in) {
  std::string text;
  std::vector<char> chunk(std::size_t{1} << 16);
  while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0)
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
  return text;
}

std::vector<std::string> specFiles(const std::vector<std::string>& inputs) {
  std::vector<std::string> files;
  for (const auto& in : inputs) {
    if (fs::is_directory(in)) {
      std::vector<std::string> here;
      for (const auto& e : fs::directory_iterator(in))
        if (e.is_regular_file() && e.path().extension() == ".json")
          here.push_back(e.path().string());
      std::sort(here.begin(), here.end());
      files.insert(files.end(), here.begin(), here.end());
    } else if (fs::exists(in)) {
      files.push_back(in);
    } else {
      throw UsageError("no such file or directory: '" + in + "'");
    }
  }
  return files;
}

// The main job on a folder of examples: one row per spec with status, branches, DOF and the
// median solve time over --repeat solves.
int cmdTable(const Args& a, const Registry& reg) {
  if (a.positional.empty()) throw UsageError("table needs a folder or spec files");
  const auto files = specFiles(a.positional);
  std::printf("%-36s %-13s %8s %-12s %10s%s\n", "name", "status", "branches", "DOF", "median us",
              a.collision ? "  free branches" : "");
  int invalid = 0;
  relpos::Workspace ws;
  relpos::Solution sol;
  for (const auto& f : files) {
    relpos::Problem pb;
    if (!loadProblem(f, reg, &pb)) {
      std::printf("%-36s %-13s\n", oneLine(fs::path(f).stem().string()).c_str(), "invalid");
      ++invalid;
      continue;
    }
    std::vector<double> us;
    us.reserve(a.repeat);
    for (int i = 0; i < a.repeat; ++i) {
      relpos::solve(pb, reg, relpos::SolverOptions(), ws, sol);
      us.push_back(sol.solve_us);
    }
    std::nth_element(us.begin(), us.begin() + us.size() / 2, us.end());
    std::string dofs;
    for (const auto& b : sol.branches) {
      std::string d = std::to_string(b.manifold->dof());
      if (dofs.find(d) == std::string::npos) dofs += (dofs.empty() ? "" : ",") + d;
    }
    std::printf("%-36s %-13s %8zu %-12s %10.2f", oneLine(pb.name).c_str(),
                relpos::toString(sol.status), sol.branches.size(),
                dofs.empty() ? "-" : dofs.c_str(), us[us.size() / 2]);
    if (a.collision) {  // the collision-free branches (SPEC.md §2 collision_free_branches)
      nlohmann::ordered_json result = resultTree(pb, sol, a.result);
      if (addCollisionFields(f, a, pb, sol, &result))
        std::printf("  %13d", result["collision_free_branches"].get<int>());
      else
        std::printf("  %13s", "invalid"), ++invalid;
    }
    std::printf("\n");
  }
  std::printf("%zu specs, %d invalid\n", files.size(), invalid);
  return invalid ? kExitInvalid : kExitOk;
}

}  // namespace relpos::cli

using namespace relpos::cli;

int main(int argc, char** argv) {
  // Past a file size limit (ulimit -f) a write fails with EFBIG and is reported like a full disk,
  // instead of the signal killing the process half-way through a line.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    if (argc < 2) throw UsageError("missing command");
    const std::string cmd = argv[1];
    // Help and version before anything is parsed or loaded: `relpos solve --help` is help, not a
    // usage error about the missing spec.
    for (int i = 1; i < argc; ++i)
      if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
        std::cout << kUsage;
        return kExitOk;
      }
    if (cmd == "--version" || cmd == "version") {
      std::cout << "relpos " << RELPOS_VERSION << " (plugin ABI " << relpos::kPluginAbiVersion
                << ")\n";
      return kExitOk;
    }
    Args a = parseArgs(argc, argv, 2);
    if (a.out_given && a.out.empty()) throw InvalidInput("-o: an empty path");
    if (a.out_given && cmd != "solve" && cmd != "batch")
      throw InvalidInput("-o: '" + cmd + "' writes to standard output only");
    Registry reg;
    relpos::registerBuiltins(reg);
    if (!loadPlugins(cmd, a, reg)) return kExitInvalid;
    reg.freeze();
    if (cmd == "solve") return cmdSolve(a, reg);
    if (cmd == "rules") return cmdRules(a, reg);
    if (cmd == "table") return cmdTable(a, reg);
    if (cmd == "batch") return cmdBatch(a, reg);
    throw UsageError("unknown command '" + cmd + "'");
  } catch (const UsageError& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n" << kUsage;
    return kExitInvalid;
  } catch (const InvalidInput& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n";
    return kExitInvalid;
  } catch (const WriteFailed& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "relpos: internal error: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  }
}
