#pragma once
// Collision filtering of one solution branch (SPEC.md §2 "Collision fields"): the verdict for its
// nearest pose, the collision-free pose nearest the initial pose, and which parameter samples are
// free.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "relpos/collision/scene.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::collision {

struct FilterOptions {
  double clearance = 0.0;
  int samples = 64;        // --collision-samples
  double window = 1.0;     // unbounded lengths: within ±window of the nearest parameters
  std::uint64_t seed = 0;  // the samples' generator (deterministic)
};

struct FreePose {
  Params parameters{};
  Isometry3d pose = Isometry3d::Identity();
};

struct BranchCollision {
  bool nearest_collides = false;
  std::vector<Contact> nearest_contacts;
  bool has_nearest_free = false;
  NearestPose nearest_free;
  std::string nearest_free_reason;
  std::vector<FreePose> free_samples;
  int blocked_samples = 0;
};

// `nearest` is the branch's nearest pose to `initial` (nearestOnBranch). nearest_free: the
// nearest pose if free; otherwise the closest free sample (or, with none free, the closest free
// probe along each parameter around the nearest parameters), pushed to the collision boundary by
// bisection towards the nearest pose and, with two or more parameters, refined by a compass
// search that only steps to free poses.
BranchCollision filterBranch(const Scene& scene, const Branch& branch, const NearestPose& nearest,
                             const Isometry3d& initial, const FilterOptions& options);

// The branch's "collision" object of SPEC.md §2.
nlohmann::ordered_json collisionToJson(const BranchCollision& c, int dof,
                                       const std::vector<std::string>& checked_against,
                                       double clearance);

}  // namespace relpos::collision
