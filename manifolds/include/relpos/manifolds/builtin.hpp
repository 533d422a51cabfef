#pragma once
#include "relpos/core/registry.hpp"

namespace relpos::manifolds {
// Registers the built-in manifold types and the separable matcher (PMF Tables III–V).
void registerBuiltinManifolds(Registry& registry);
// Registers the mixed (non-separable) manifolds and their matcher (Somani 004 §IV-A).
void registerMixedManifolds(Registry& registry);
}  // namespace relpos::manifolds
