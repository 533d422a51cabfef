#pragma once
// The nearest pose of a branch whose only searched parameter is an angle (the others have closed
// forms given it): a cylinder grasp's turn about the axis, a radial grasp's approach angle.
#include "relpos/core/manifold.hpp"

namespace relpos::detail {

// Whether θ_i alone is searched and bounded, or periodic: the case nearestAlongOneAngle handles.
bool searchesOneBoundedAngle(const Manifold& m, const Parameter* par, int* i);

// The angle θ_i (the one searched parameter) of the pose nearest X, the others set in closed form:
// samples evenly over the turn (or the bounds, both ends included, since a bound is where a ranged
// minimum often lies), then Brent's method over the two sample steps around each of the two
// nearest samples that are nearer than their neighbours (and around a bounded angle's projection),
// or, from a sample near a kink of the rotation, the kink's steps (kink_certificate.hpp). `best`
// holds the projection on entry and the answer on return; *best_d its distance. True when the
// answer is a kink proven a local minimum. `arc`: par[i] holds, as its bounds, the arc of a
// periodic angle the nearest pose lies on (Manifold::nearestArc): angles are brought onto the
// arc's turn, and it is sampled more finely than a turn (15° apart against 30°), in no more poses.
bool nearestAlongOneAngle(const Manifold& m, const Isometry3d& X, const Parameter* par, int i,
                          bool arc, Params* best, double* best_d);

}  // namespace relpos::detail
