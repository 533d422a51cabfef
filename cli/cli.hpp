#pragma once
// What the relpos command's files share: options, spec discovery and loading, the commands.
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "errors.hpp"
#include "relpos/collision/scene.hpp"
#include "relpos/core/diagnostic.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/report/evaluate.hpp"

namespace relpos::cli {

struct Args {
  int jobs = 0;  // batch: worker threads (0: every core)
  std::vector<std::string> positional;
  bool coverage = false;
  relpos::ReportOptions result;  // --samples, --window, --seed, --clearance, --collision-samples
  std::string out;               // -o
  bool out_given = false;
  int repeat = 200;
  std::vector<std::string> plugins;
  bool allow_override = false;
  bool collision = false;
  bool collision_option = false;  // --clearance or --collision-samples given
  bool degrees = false;           // --angles deg
  std::string format;             // export: --format
  bool samples_given = false;     // --samples given (view's default is not 0)
  bool window_given = false;      // --window given (view's default is the problem's size)
};

// The options after the command (argv[first]...). Throws UsageError.
Args parseArgs(int argc, char** argv, int first);
// --clearance and --collision-samples mean nothing without --collision: a usage error, not an
// option silently ignored (solve, batch and table).
void requireCollisionForItsOptions(const Args& a);

// The spec files of folders (their *.json in name order) and files given on the command line.
std::vector<std::string> specFiles(const std::vector<std::string>& inputs);

// Everything left in the stream, read in chunks (it may be a pipe, whose size is unknown).
std::string readAll(std::istream& in);

// Diagnostics on stderr, one per line, "FILE: path: message" (warnings marked).
void printDiagnostics(const std::string& file, const std::vector<relpos::Diagnostic>& errors,
                      const std::vector<relpos::Diagnostic>& warnings);

// Reads and parses a spec file, its problems on stderr; false when it is not a valid spec.
bool loadProblem(const std::string& file, const relpos::Registry& reg, relpos::Problem* pb);

// The collision scene of a spec file, its meshes' problems on stderr; nullptr when it cannot be
// built.
std::unique_ptr<relpos::collision::Scene> loadScene(const std::string& file,
                                                    const relpos::Problem& pb,
                                                    relpos::collision::MeshCache& cache);

// The report of a solved spec file into *report; with `collision`, against its meshes. False when
// the meshes cannot be read (their problems on stderr); a throw while reading them is an answer
// (unhandledAfterThrow), as when the filter itself throws.
bool reportOf(const std::string& file, const relpos::Problem& pb, const relpos::Solution& sol,
              const relpos::ReportOptions& options, bool collision, relpos::Report* report);

// Loads, in order, the plugins of RELPOS_PLUGIN_PATH, of --plugin, and of the "plugins" lists of
// the specs the command will read. The first failure is one line on stderr; false then.
bool loadPlugins(const std::string& cmd, const Args& a, relpos::Registry& reg);

// The commands (docs/spec.md §3), one file each in commands/.
int cmdSolve(const Args& a, const relpos::Registry& reg);
int cmdRules(const Args& a, const relpos::Registry& reg);
int cmdTable(const Args& a, const relpos::Registry& reg);
int cmdBatch(const Args& a, const relpos::Registry& reg);
int cmdExport(const Args& a, const relpos::Registry& reg);
int cmdView(const Args& a, const relpos::Registry& reg);

}  // namespace relpos::cli
