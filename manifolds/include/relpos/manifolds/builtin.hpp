#pragma once
#include "relpos/core/registry.hpp"

namespace relpos::manifolds {
// Registers the built-in manifold types and the separable matcher (PMF Tables III–V).
void registerBuiltinManifolds(Registry& registry);
}  // namespace relpos::manifolds
