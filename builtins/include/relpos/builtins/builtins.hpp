#pragma once
// Every built-in constraint type, rule family and manifold in one registry.
#include "relpos/core/registry.hpp"

namespace relpos {
// Registers every built-in constraint type, rule and manifold (in that order), then returns.
// Does not freeze.
void registerBuiltins(Registry& registry);
// One frozen registry holding the built-ins, made on first use (tests, benchmarks, tools).
const Registry& builtinRegistry();
}  // namespace relpos
