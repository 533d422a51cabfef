// Finding, reading and reporting on spec files: what every command that reads specs shares.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/text.hpp"

namespace fs = std::filesystem;

namespace relpos::cli {

// Diagnostics go to stderr one per line, whatever the names they quote hold (a newline, 0xFF).
void printDiagnostics(const std::string& file, const std::vector<relpos::Diagnostic>& errors,
                      const std::vector<relpos::Diagnostic>& warnings) {
  // formatDiagnostic's line is one line of valid UTF-8 already (the one place that escapes).
  for (const auto& w : warnings) std::cerr << relpos::formatDiagnostic(file, w) << " (warning)\n";
  for (const auto& e : errors) std::cerr << relpos::formatDiagnostic(file, e) << "\n";
}

bool loadProblem(const std::string& file, const Registry& reg, relpos::Problem* pb) {
  relpos::ParseResult r = relpos::parseSpecFile(file, reg);
  printDiagnostics(file, r.errors, r.warnings);
  if (!r.problem) return false;
  *pb = std::move(*r.problem);
  return true;
}

// The collision scene of a spec file, its meshes' problems reported on stderr; nullptr when it
// cannot be built.
std::unique_ptr<relpos::collision::Scene> loadScene(const std::string& file,
                                                    const relpos::Problem& pb,
                                                    relpos::collision::MeshCache& cache) {
  std::vector<relpos::Diagnostic> errors, warnings;
  auto scene = relpos::collision::buildScene(pb, fs::path(file).parent_path().string(), cache,
                                             &errors, &warnings);
  printDiagnostics(file, errors, warnings);
  return scene;
}

bool reportOf(const std::string& file, const relpos::Problem& pb, const relpos::Solution& sol,
              const relpos::ReportOptions& options, bool collision, relpos::Report* report) {
  if (!collision) {
    relpos::evaluate(pb, sol, options, *report);
    return true;
  }
  relpos::collision::MeshCache cache;
  std::unique_ptr<relpos::collision::Scene> scene;
  try {
    scene = loadScene(file, pb, cache);
  } catch (const std::exception& e) {
    relpos::evaluate(pb, relpos::unhandledAfterThrow(sol, "filtering collisions", e.what()),
                     options, *report);
    report->collision_checked = true;
    return true;
  }
  if (!scene) return false;
  relpos::evaluate(pb, sol, options, *report, scene.get());
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

}  // namespace relpos::cli
