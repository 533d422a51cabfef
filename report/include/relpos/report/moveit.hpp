#pragma once
// A branch as MoveIt goal constraints (moveit_msgs/Constraints; docs/spec.md §3.11, issue 17):
// a position constraint (a box, on a point of the mobile object) and an orientation constraint
// (a target orientation with tolerances about the mobile object's axes, XYZ Euler angles).
// MoveIt's constraints are a product — positions times orientations — so only a branch whose
// poses are such a product is exact; otherwise the constraints are conservative: every pose they
// admit is a pose of the branch (inside means valid), not every pose of the branch is admitted.
#include <string>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

struct MoveItGoal {
  bool exact = false;  // the constraints admit exactly the branch's poses (to rounding)
  std::string why;     // !exact: what they leave out
  // The position constraint: the point target_point_offset (in the mobile object's frame) within
  // a box (its pose in the world, its full side lengths; a side that does not vary is 1e-9 of
  // the problem's size, as MoveIt's box needs some thickness).
  Vector3d target_point_offset{0, 0, 0};
  Isometry3d box_pose = Isometry3d::Identity();
  Vector3d box_dimensions{0, 0, 0};
  // The orientation constraint: within these absolute tolerances of `orientation`, about the
  // mobile object's x, y and z axes (XYZ Euler angles of orientation⁻¹ · R); 1e-9 for an angle
  // that does not vary.
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Vector3d axis_tolerances{0, 0, 0};
  bool windowed = false;  // an unbounded slide bounded to ±window (as the TSR export does)
};

// The goal constraints of `branch` about parameters `at` (its nearest pose's); `window` as
// tsrChainOf's.
MoveItGoal moveitGoalOf(const Problem& problem, const Branch& branch, const Params& at,
                        double window);

}  // namespace relpos
