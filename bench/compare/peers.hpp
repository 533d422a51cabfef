#pragma once
// The two peers bench/compare runs beside relpos, each from the problem's initial pose, each
// returning one pose (they find one solution, not the solution set).
#include <string>

#include "relpos/core/problem.hpp"

namespace relpos::compare {

struct PeerResult {
  bool converged = false;  // the peer says it found a solution
  Isometry3d pose = Isometry3d::Identity();
  int dof = -1;             // degrees of freedom the peer reports (-1: none)
  std::string unsupported;  // non-empty: the problem cannot be stated to this peer (why)
};

// SolveSpace's constraint library (libslvs): the mobile object is a 3-D workplane frame (origin
// point + normal quaternion, the unknowns); each body-fixed point is a 3-D point tied to that
// frame by a projected coincidence with a 2-D point of constant parameters (u, v) and a
// point–plane distance w. Exact constraints only: ranges must have been replaced before.
PeerResult solveWithSolveSpace(const Problem& p);

// An iterative projection in the style of Somani 004 ref. [6]: NLopt's SLSQP over a pose
// increment ξ (rotation vector, translation) from the initial pose, minimising the sum of squared
// residuals of the exact constraints, each range an inequality (its violation ≤ 0), gradients
// by central differences.
PeerResult solveWithNlopt(const Problem& p);

// A min/max constraint (a distance or angle without a single value).
inline bool isRange(const InputConstraint& c) {
  return (c.type == "distance" || c.type == "angle") && !c.has_value;
}

// The problem with every range replaced by its midpoint (a finite bound when one-sided).
Problem midRangeVariant(const Problem& p);

}  // namespace relpos::compare
