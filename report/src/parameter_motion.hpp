#pragma once
// The motion each parameter of a branch makes (relpos/io/report.hpp ParameterMotion), computed
// from the branch's pose function alone, so that it holds for every manifold, a plugin's too.
#include <array>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/io/report.hpp"

namespace relpos::detail {

// The motion of every parameter of `branch` at parameters `at` (its nearest pose's), by central
// differences of pose(θ) within the bounds, and the ranged input constraint each range parameter
// spans. Runs the branch's code: a throw beside `at` makes that motion unknown (the stage that
// needs those poses reports it); one at `at` itself is let through.
void parameterMotions(const Problem& problem, const Branch& branch, const Params& at,
                      std::array<ParameterMotion, kMaxDof>& out);

// The screw taking pose Xa to Xb, per unit of a parameter that changed by `span`: exact for a
// rigid motion whatever its size (a turn's axis point the one nearest `origin`). `scale`: the
// problem's size, below 1e-9 of which an advance is rounding.
ParameterMotion screwBetween(const Isometry3d& Xa, const Isometry3d& Xb, double span,
                             const Vector3d& origin, double scale);

// Parameter i's two values about at[i] (in *a and *b, the others as at): ± step·(1 + |at[i]|), at
// most a quarter of a bounded range, within the bounds. False when the bounds pin it (the two
// less than half a step apart).
bool stepAround(const Manifold& m, const Params& at, int i, double step, Params* a, Params* b);

// The motion of parameter i of m about `at`, between the poses `step` (relative; at most a quarter
// of a bounded range) to either side within its bounds: what the report writes (step 1e-4: the
// instantaneous motion to about 1e-8), and exactly the parameter's screw whatever the step when
// the parameter turns about a fixed line or slides along a fixed direction. A turn's axis point
// is the one nearest `origin` (the pose at `at`'s origin, which the caller has computed once for
// every parameter).
ParameterMotion motionAlong(const Manifold& m, const Params& at, const Vector3d& origin, int i,
                            double step, double scale);

}  // namespace relpos::detail
