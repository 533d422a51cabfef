#pragma once
// What the pose models (pose_model.cpp) and the screw products (screw_product.cpp) share: the
// product's pose, the check points and the separable product's parts.
#include <optional>
#include <vector>

#include "relpos/report/pose_model.hpp"

namespace relpos::detail {

// Rigid factors compose as X = Π exp(…)·X(θ*); an orienting one turns the orientation only, a
// moving one carries the point `pivot` of the object (in its frame) only.
Isometry3d product(const std::vector<ScrewFactor>& order, const Params& theta, const Params& at,
                   const Isometry3d& X_at, const Vector3d& pivot);

// Parameter p's range: its bounds, ± window about `at` where it has none; a periodic one a turn.
void boxOf(const Parameter& p, double at, double window, double* lo, double* hi);

// Parameters drawn over the box, with its corners first: where a wrong order shows most.
std::vector<Params> checkPoints(const Manifold& m, const Params& at, double window);

// The point of the object its turns are about, in its frame: where the axes of the parameters
// that turn it meet (a fingertip on a sphere, the object turning freely about it), so that the
// point's position depends on the other parameters only; the origin when they do not meet.
Vector3d pivotOf(const Manifold& m, const Params& at, const Isometry3d& X_at, double scale);

// A separable branch's product: per parameter, the turn it gives the orientation (about the
// origin: only the axis matters) and the motion it gives the pivot — a slide when its three
// positions about θ* are on a line, else the turn about the axis of the circle through them —
// each part's order found apart; checked like a rigid product. The orienting factors first.
std::optional<std::vector<ScrewFactor>> separableProduct(const Manifold& m, const Params& at,
                                                         const Isometry3d& X_at,
                                                         const Vector3d& pivot,
                                                         const std::vector<Params>& points,
                                                         double scale);

}  // namespace relpos::detail
