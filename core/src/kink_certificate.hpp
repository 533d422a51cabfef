#pragma once
// The nearest pose at a kink of the metric: where the rotation is already right and only the
// position differs, the distance ‖Δt‖ + angle has no gradient, a Newton step on it does not
// converge, and a pattern search spends dozens of poses confirming the point (issue 18).
#include "relpos/core/manifold.hpp"

namespace relpos::detail {

// The rotation ε (radians) by which X's may miss every rotation of the branch and still count as
// reached: the certificate's model carries it. It proves nothing where the branch's nearest
// rotation misses X's by more (twice this, to be clear of the model's rounding).
constexpr double kKinkReach = 1e-4;

// From *best (its distance *best_d), steps on the rotation's residual alone, each taken only when
// it lowers the distance, to the point where the rotation equals X's; there, true when that point
// is a strict local minimum of the distance: with J_r and J_t the rotation's and the translation's
// residual Jacobians in the searched parameters (central differences), J_r of full column rank
// and g = J_tᵀ Δt/‖Δt‖, the distance grows in every direction by at least
// (1 − √(gᵀ (J_rᵀJ_r)⁻¹ g)) ‖J_r δ‖ to first order, so gᵀ (J_rᵀJ_r)⁻¹ g < 1 proves it; every
// probe of the differences is checked not to be nearer as well. Where X's rotation lies a small
// ε (≤ 1e-4) off every rotation of the branch (an initial pose written with 8 digits), the same
// test holds at the minimum of the model ‖Δt‖ + gᵀδ + √(ε² + ‖J_r δ‖²), which the steps end on.
// *best_d +inf: *best not weighed yet (its distance is then set from the first residuals).
// *start_d (if given): the distance at *best as given, NaN where none was weighed.
// False (the search goes on from *best, never farther than before) for more than three searched
// parameters, a rotation that cannot be reached, or a point the translation pulls away from.
bool settleOnRotationKink(const Manifold& m, const Isometry3d& X, const Parameter* par,
                          Params* best, double* best_d, double* start_d = nullptr);

}  // namespace relpos::detail
