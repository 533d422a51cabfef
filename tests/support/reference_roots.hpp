#pragma once
// An independent reference solution set for a 0-DOF spec (issue 15): thousands of
// Levenberg-Marquardt solves from random initial poses on a minimal pose parametrisation (a
// rotation vector and a translation about the current pose), with the residuals of the tests'
// evaluator (evaluator.hpp, docs/spec.md §1.9 read directly), not relpos's encoding; every root
// verified by the evaluator and deduplicated by pose distance. Deterministic for a seed. It finds
// what random starts reach: a lower bound on the solution set, never a proof of completeness.
#include <cstdint>
#include <vector>

#include "relpos/core/problem.hpp"

namespace relpos::test {

struct ReferenceOptions {
  int starts = 4000;
  std::uint64_t seed = 1;
  int max_iterations = 200;
  // A root holds every constraint to within this (the evaluator's worst violation).
  double verify_tolerance = 1e-9;
  // Two roots closer than this (poseDistance, or line distance below) are one.
  double duplicate_distance = 1e-6;
  // The mobile features all lie on one line (the four-spheres problem): spin about it and slide
  // along it are free, so a root is the world line, compared as an undirected line.
  bool line_quotient = false;
};

struct ReferenceRoots {
  std::vector<Isometry3d> poses;  // one pose per distinct root, in the order first found
  int starts = 0;
  int converged = 0;      // starts that ended on a verified root
  std::vector<int> hits;  // per pose: how many starts reached it
};

ReferenceRoots referenceRoots(const Problem& p, const ReferenceOptions& options = {});

// One Levenberg-Marquardt solve from X0; true with *X the root when the evaluator verifies it.
bool newtonSolve(const Problem& p, const Isometry3d& X0, const ReferenceOptions& options,
                 Isometry3d* X);

// The world line carried by the mobile line feature at X, as (foot point nearest the origin,
// unit direction with a sign fixed by its largest component): the same for a line and its
// reverse. For line_quotient problems.
struct WorldLine {
  Vector3d foot, direction;
};
WorldLine undirectedLine(const Problem& p, const Isometry3d& X);
double lineDistance(const WorldLine& a, const WorldLine& b);

// The smallest singular value over the largest of the constraints' Jacobian at X in the pose's
// six local coordinates (rotation vector scaled by the problem's size, translation): near 0 at a
// pose that is not isolated.
double jacobianConditioning(const Problem& p, const Isometry3d& X, int* rank = nullptr);

}  // namespace relpos::test
