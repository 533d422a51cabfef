// relpos view (docs/spec.md §3.12): a spec's answer as one self-contained HTML page.
#include <filesystem>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "output_file.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/viewer/page.hpp"

namespace relpos::cli {

int cmdView(const Args& a, const Registry& reg) {
  if (a.positional.size() != 1) throw UsageError("view takes exactly one spec file");
  requireCollisionForItsOptions(a);
  const std::string& file = a.positional[0];
  const std::string out =
      a.out.empty() ? std::filesystem::path(file).stem().string() + ".html" : a.out;
  checkOutput(out, a.positional, OutputMode::kReplace);
  relpos::Problem pb;
  if (!loadProblem(file, reg, &pb)) return kExitInvalid;
  const relpos::Solution sol = relpos::solve(pb, reg);
  relpos::ReportOptions options = a.result;
  if (!a.samples_given) options.samples = 12;
  // Unbounded lengths slide (and are sampled) within the problem's own size, not a metre: a
  // 5 cm part stays in the picture.
  const double size = pb.lengthScale();
  if (!a.window_given) options.window = size > 0.0 ? size : 1.0;
  relpos::Report report;
  if (!reportOf(file, pb, sol, options, a.collision, &report)) return kExitInvalid;
  relpos::viewer::ViewOptions view;
  view.window = options.window;
  view.degrees = a.degrees;
  view.spec_dir = std::filesystem::path(file).parent_path().string();
  std::string html;
  std::vector<relpos::Diagnostic> errors, warnings;
  const bool ok = relpos::viewer::writePage(pb, sol, report, view, &html, &errors, &warnings);
  printDiagnostics(file, errors, warnings);
  if (!ok) return kExitInvalid;
  replaceFile(out, html);
  std::cerr << "relpos: wrote " << out << " (" << report.branches.size()
            << (report.branches.size() == 1 ? " branch" : " branches") << ")\n";
  return kExitOk;
}

}  // namespace relpos::cli
