#pragma once
// What the relpos command's files share: options, exit codes, spec discovery, collision fields.
#include <istream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "errors.hpp"
#include "relpos/collision/branch_filter.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/result_writer.hpp"

namespace relpos::cli {

inline const char* const kUsage =
    "usage:\n"
    "  relpos solve SPEC.json [--samples N] [--window W] [--seed S] [-o OUT.json]\n"
    "               [--collision [--clearance C] [--collision-samples N]]\n"
    "  relpos rules [--coverage DIR-or-SPEC...]\n"
    "  relpos table DIR-or-SPEC... [--repeat N] [--collision ...]\n"
    "  relpos batch DIR-or-FILE.jsonl [--jobs N] [-o OUT.jsonl] [solve options]\n"
    "  relpos --version\n"
    "every command: [--plugin LIB.so]... [--allow-override] [--help];\n"
    "  RELPOS_PLUGIN_PATH=FILE-or-DIR:...\n";

struct Args {
  int jobs = 0;  // batch: worker threads (0: every core)
  std::vector<std::string> positional;
  bool coverage = false;
  relpos::ResultOptions result;
  std::string out;  // -o
  bool out_given = false;
  int repeat = 200;
  std::vector<std::string> plugins;
  bool allow_override = false;
  bool collision = false;
  bool collision_option = false;  // --clearance or --collision-samples given
  relpos::collision::FilterOptions filter;
};

// The spec files of folders (their *.json in name order) and files given on the command line.
std::vector<std::string> specFiles(const std::vector<std::string>& inputs);

// Everything left in the stream, read in chunks (it may be a pipe, whose size is unknown).
std::string readAll(std::istream& in);

// The result line as a JSON tree, to add fields to (collision filtering): the writer writes UTF-8
// whatever the names it copies hold, so the parse cannot fail on them.
nlohmann::ordered_json resultTree(const relpos::Problem& pb, const relpos::Solution& sol,
                                  const relpos::ResultOptions& options);

// Adds SPEC.md §2's collision fields to a result: a `collision` object per branch and
// `collision_free_branches`. False when the scene cannot be built (errors say why).
bool collisionFields(const std::string& spec_dir, const Args& a, const relpos::Problem& pb,
                     const relpos::Solution& sol, relpos::collision::MeshCache& cache,
                     nlohmann::ordered_json* result, std::vector<relpos::Diagnostic>* errors,
                     std::vector<relpos::Diagnostic>* warnings);

// relpos batch (SPEC.md §3).
int cmdBatch(const Args& a, const relpos::Registry& reg);

}  // namespace relpos::cli
