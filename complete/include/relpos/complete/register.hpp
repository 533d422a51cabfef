#pragma once
// Registers the numeric stage (solveComplete, docs/spec.md §8) as the registry's fallback: what
// the rules leave unhandled goes to it. registerBuiltins calls this.
#include "relpos/core/registry.hpp"

namespace relpos::complete {

void registerStage(Registry& registry);

}  // namespace relpos::complete
