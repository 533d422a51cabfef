// An SDK user's program against the installed relpos::collision and relpos::report (issue 17):
// solve a spec with meshes, build its collision scene and filter the branches, as
// `relpos solve --collision` does. Exit 0 when the verdicts are there and say what the spec's
// comment says: the part's nearest pose on the table is free, and some branch is collision-free.
#include <cstdio>
#include <filesystem>

#include "relpos/builtins/builtins.hpp"
#include "relpos/collision/scene.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"

int main() {
  const std::string spec = COLLISION_SPEC;
  const relpos::ParseResult r = relpos::parseSpecFile(spec, relpos::builtinRegistry());
  if (!r.problem) return std::puts("the spec did not parse"), 1;
  const relpos::Solution s = relpos::solve(*r.problem, relpos::builtinRegistry());
  relpos::collision::MeshCache cache;
  std::vector<relpos::Diagnostic> errors, warnings;
  const auto scene = relpos::collision::buildScene(
      *r.problem, std::filesystem::path(spec).parent_path().string(), cache, &errors, &warnings);
  if (!scene) return std::puts("no scene"), 1;
  const relpos::Report report = relpos::evaluate(*r.problem, s, relpos::ReportOptions(), scene.get());
  std::printf("%zu branches, %d collision-free, checked against %zu objects\n",
              report.branches.size(), report.collision_free_branches,
              report.checked_against.size());
  const bool ok = report.collision_checked && report.collision.size() == report.branches.size() &&
                  !report.branches.empty() && report.collision_free_branches > 0 &&
                  !report.checked_against.empty();
  return ok ? 0 : 1;
}
