#pragma once
// The tolerance policy's first step (issue 13): before any rule runs, the geometry of every
// decomposed constraint set is centred — fixed points about the middle of their bounding box in
// the world, mobile points about theirs in the mobile frame — and the problem's size is measured
// on the centred geometry. Lengths are then decided relative to that size, and the rules compute
// with coordinates of the problem's own size: a task moved 10⁶ away, or whose part frame lies far
// from its features, is decided as it is at the origin, and one scaled by 10⁻⁶ or 10⁶ as it is in
// metres (floating point is relative; only the tolerance had an absolute floor).
#include <string>
#include <vector>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos::detail {

struct Centring {
  Vector3d offset_W = Vector3d::Zero();  // subtracted from every fixed point (world)
  Vector3d offset_M = Vector3d::Zero();  // subtracted from every mobile point (mobile frame)
  double size = 0.0;  // the longest diagonal of the two sides' boxes, or a longer length value
  double magnitude =
      0.0;  // largest coordinate before centring: what the input's rounding scales with
  bool centred = false;  // false: nothing was moved (a plugin's custom kind holds points we
                         // cannot read, or centring was not asked for)
};

// Measures the sets and, when `centre`, moves their geometry (every set is an alternative of the
// same problem, so one offset serves all).
Centring centreSets(std::vector<ConstraintSet>& sets, bool centre);

// The largest coordinate that went into placing the fixed features in the world (their points in
// the fixed frame and the frame's origin): a world point R p + t near the origin still carries
// the rounding of |p| and |t|, which the placed coordinates no longer show (a fixed frame 1e6
// away puts errors of 1e-10 into features a unit apart). Joins Centring::magnitude.
double placementMagnitude(const Problem& problem);

// The tolerance for a measured problem: lengths relative to its size, never below what rounding
// the input at its magnitude can cause (the computation's own error), angles as given.
Tolerance toleranceFor(const Centring& c, double relative_length, double angle);

// Empty when the problem's numbers are in the range the solver computes with, else why not:
// squares of lengths beyond 1e100 overflow, and of lengths below 1e-100 underflow.
// The mobile object's initial pose counts too: only the nearest poses use it, but their distances
// from it would overflow.
const char* outOfRange(const Centring& c, const Problem& problem);

// How many times the coordinates' rounding may widen the requested length tolerance (the floor
// of toleranceFor) before the problem is no longer decided as asked: beyond it the answer is
// unhandled. A task of size 3 placed 1e6 away widens it about fivefold, features 7 mm apart there
// about 2,000-fold (directions still known to 2e-6 rad); 1e13 away, the floor would pass
// perpendicular planes for parallel.
inline constexpr double kMaxRoundingWidening = 1e5;

// Empty when the tolerance decided is within kMaxRoundingWidening of the one asked for, else why
// the problem cannot be decided there.
std::string tooFarFromOrigin(const Centring& c, const Tolerance& decided, double relative_length);

}  // namespace relpos::detail
