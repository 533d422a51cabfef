#pragma once
// The nearest pose near a kink the certificate cannot settle (kink_certificate.hpp): the
// translation pulls the pose off X's rotation, and the minimum lies where the translation
// distance is zero (the rotation turns the mobile point onto X's origin) or at a smooth point
// between the kinks. A pattern search crawls along such a crease; the distance's first-order
// model, a sum of two norms, is convex and its minimum a step that crosses it.
#include "relpos/core/manifold.hpp"
#include "residual_model.hpp"

namespace relpos::detail {

// The δ minimising ‖a + A δ‖ + ‖b + B δ‖ ([A; B] of full column rank: a minimum exists): the best
// of its two kinks (a + Aδ = 0 with ‖b + Bδ‖ least along it; b + Bδ = 0) and of damped Newton on
// the smooth sum from δ = 0. The sum is convex: one of the three is its minimum. (Reweighted least
// squares creeps towards a kink, one bit a step, and stopped short of it.)
Step normSumMinimum(const Jacobian& A, const Vector3d& a, const Jacobian& B, const Vector3d& b);

// From *best, steps to the minimum of the distance's first-order model (the translation's and the
// rotation's residuals, linearised by central differences), each taken only when it lowers the
// distance (else a quarter, a sixteenth of it). True when the model's step has shrunk below what
// the distance resolves (1e-10): a point no first-order step improves on. False where some
// direction of the parameters moves neither residual. Never farther than before.
bool descendOnDistanceModel(const Manifold& m, const Isometry3d& X, const Parameter* par,
                            Params* best, double* best_d);

}  // namespace relpos::detail
