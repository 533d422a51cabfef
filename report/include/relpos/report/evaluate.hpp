#pragma once
// The report stage (docs/spec.md §2): from a solved problem to the values the result holds — per
// branch the pose nearest the initial pose, samples and, against a collision scene, the
// collision verdicts; the best branch. Everything that runs a branch's code (a plugin's manifold
// included) runs here, so that the writer (relpos/io/result_writer.hpp) only serialises.
#include <cstdint>
#include <string>

#include "relpos/collision/scene.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/io/report.hpp"

namespace relpos {

struct ReportOptions {
  int samples = 0;         // poses per branch (--samples)
  double window = 1.0;     // half-width for unbounded length parameters (--window)
  std::uint64_t seed = 0;  // the samples' generator (deterministic)
  // With a scene only:
  double clearance = 0.0;      // --clearance
  int collision_samples = 64;  // --collision-samples: the filter's own samples per branch
};

// The report of `solution` (of `problem`), into `report` (reused: its buffers keep their
// capacity). With a scene, the collision fields too. Never throws: a branch's code that throws
// makes the report that of unhandledAfterThrow(solution, …) naming the plugin — "writing the
// result" for the nearest pose and samples, "filtering collisions" for the collision filter.
void evaluate(const Problem& problem, const Solution& solution, const ReportOptions& options,
              Report& report, const collision::Scene* scene = nullptr);
Report evaluate(const Problem& problem, const Solution& solution, const ReportOptions& options,
                const collision::Scene* scene = nullptr);

// evaluate then writeReport(kResultLine): the batch's result line, into `out`.
void writeResultLine(const Problem& problem, const Solution& solution, const ReportOptions& options,
                     std::string& out);

}  // namespace relpos
