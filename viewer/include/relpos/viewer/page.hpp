#pragma once
// relpos view (docs/spec.md §3.12): a solved problem as one self-contained HTML page — the fixed
// object's features and mesh, the obstacles, the mobile object at each branch's nearest pose,
// ghosts at its samples, and a slider per branch parameter that moves it. The page's script
// (three.js and the viewer's own) is compiled in, so the page needs no network and no files.
#include <cstdint>
#include <string>
#include <vector>

#include "relpos/core/diagnostic.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/io/report.hpp"

namespace relpos::viewer {

struct ViewOptions {
  double window = 1.0;     // unbounded length parameters' sliders: ± window about the nearest pose
  bool degrees = false;    // angles shown in degrees (--angles deg)
  std::string spec_dir;    // meshes' relative paths are relative to it
  int table_poses = 4096;  // a branch that is no product of screws: poses on a grid, at most these
};

// The page of `problem`, solved as `solution`, reported as `report` (its nearest poses, samples
// and, when checked, collisions). False with the problems in *errors (a mesh that cannot be read,
// its JSON path named) and no page; warnings (an open mesh) in *warnings.
bool writePage(const Problem& problem, const Solution& solution, const Report& report,
               const ViewOptions& options, std::string* html, std::vector<Diagnostic>* errors,
               std::vector<Diagnostic>* warnings);

}  // namespace relpos::viewer
