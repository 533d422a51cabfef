// relpos solve (docs/spec.md §3): one spec, its result document indented.
#include <iostream>
#include <string>

#include "cli.hpp"
#include "output_file.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/result_writer.hpp"

namespace relpos::cli {

int cmdSolve(const Args& a, const Registry& reg) {
  if (a.positional.size() != 1) throw UsageError("solve takes exactly one spec file");
  requireCollisionForItsOptions(a);
  // Before solving: an -o that cannot be written is known now, not after the work.
  if (!a.out.empty()) checkOutput(a.out, a.positional, OutputMode::kReplace);
  relpos::Problem pb;
  if (!loadProblem(a.positional[0], reg, &pb)) return kExitInvalid;
  relpos::Workspace ws;
  relpos::Solution sol;
  relpos::solve(pb, reg, relpos::SolverOptions(), ws, sol);
  relpos::Report report;
  if (!reportOf(a.positional[0], pb, sol, a.result, a.collision, &report)) return kExitInvalid;
  std::string text;
  relpos::ResultFormat format = relpos::kResultDocument;
  format.degrees = a.degrees;
  relpos::writeReport(report, format, text);
  text += '\n';
  if (!a.out.empty()) {
    replaceFile(a.out, text);
    return kExitOk;
  }
  std::cout << text << std::flush;
  if (!std::cout) throw WriteFailed("standard output: cannot write the result");
  return kExitOk;
}

}  // namespace relpos::cli
