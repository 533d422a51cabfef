// relpos table (docs/spec.md §3): one row per spec, with the median solve time.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/text.hpp"

namespace fs = std::filesystem;

namespace relpos::cli {

// The main job on a folder of examples: one row per spec with status, branches, DOF and the
// median solve time over --repeat solves.
int cmdTable(const Args& a, const Registry& reg) {
  if (a.positional.empty()) throw UsageError("table needs a folder or spec files");
  requireCollisionForItsOptions(a);
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
    if (a.collision) {  // the collision-free branches (docs/spec.md §2 collision_free_branches)
      relpos::collision::MeshCache cache;
      if (const auto scene = loadScene(f, pb, cache)) {
        relpos::Report report;
        relpos::evaluate(pb, sol, a.result, report, scene.get());
        std::printf("  %13d", report.collision_free_branches);
      } else {
        std::printf("  %13s", "invalid"), ++invalid;
      }
    }
    std::printf("\n");
  }
  std::printf("%zu specs, %d invalid\n", files.size(), invalid);
  return invalid ? kExitInvalid : kExitOk;
}

}  // namespace relpos::cli
