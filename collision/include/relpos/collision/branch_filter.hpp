#pragma once
// Collision filtering of one solution branch (docs/spec.md §2 "Collision fields"): the verdict for
// its nearest pose, the collision-free pose nearest the initial pose, and which parameter samples
// are free. Data only: the writer (relpos/io/result_writer.hpp) writes it as the branch's
// "collision" object.
#include <cstdint>

#include "relpos/collision/scene.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/report.hpp"

namespace relpos::collision {

struct FilterOptions {
  double clearance = 0.0;
  int samples = 64;        // --collision-samples
  double window = 1.0;     // unbounded lengths: within ±window of the nearest parameters
  std::uint64_t seed = 0;  // the samples' generator (deterministic)
};

using FreePose = SamplePose;
using BranchCollision = CollisionReport;

// `nearest` is the branch's nearest pose to `initial` (nearestOnBranch). nearest_free: the
// nearest pose if free; otherwise the closest free sample (or, with none free, the closest free
// probe along each parameter around the nearest parameters), pushed to the collision boundary by
// bisection towards the nearest pose and, with two or more parameters, refined by a compass
// search that only steps to free poses.
BranchCollision filterBranch(const Scene& scene, const Branch& branch, const NearestPose& nearest,
                             const Isometry3d& initial, const FilterOptions& options);

}  // namespace relpos::collision
