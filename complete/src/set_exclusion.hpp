#pragma once
// The proof behind the numeric stage's `inconsistent` for ranges and sets of poses (docs/spec.md
// §8.8): that no pose meets a condition system (pose_conditions.hpp), by interval branch and
// prune over every pose in reach. Rotations are four boxes of the quaternion charts
// (1, a, b, c) about the identity and the half turns about x, y and z, |a|, |b|, |c| ≤ 1, which
// cover every rotation (each quaternion has a largest component); the translation is bounded
// by the conditions that bound the position (a distance's upper end, a plane offset's range).
// Each box is pruned when one condition's enclosure (natural ∩ mean-value form, outward-rounded)
// misses its range widened by the tolerances, else contracted through that linear form, else
// split. A proof records which constraints pruned or contracted its boxes (and bounded the
// translation): those alone are then proven to conflict.
#include <string>

#include "pose_conditions.hpp"
#include "relpos/core/fundamental.hpp"

namespace relpos::complete::detail {

struct ExcludeOptions {
  int max_boxes = 6000;
  // How far from its range a condition may be and still count as met: an input constraint's
  // tolerance (the length one over the system's scale; radians).
  double length_tolerance = 0.0;
  double angle_tolerance = 0.0;
};

struct PoseExclusion {
  bool proven = false;     // no pose meets the conditions of the active constraints
  int boxes = 0;           // boxes examined
  SourceMask used = 0;     // the constraints the proof used: they alone conflict
  bool unbounded = false;  // not proven as the conditions do not bound the position
  std::string why;         // when not proven
};

// Whether no pose meets the conditions of `system` whose constraint is in `active` (bit i:
// input constraint i; constraints from 64 on share bit i mod 64).
PoseExclusion excludeEveryPose(const ConditionSystem& system, SourceMask active,
                               const ExcludeOptions& options);

}  // namespace relpos::complete::detail
