#pragma once
// Registers the numeric stage (solveComplete, docs/spec.md §8) as the registry's fallback: what
// the rules leave unhandled goes to it. registerBuiltins calls this.
#include "relpos/complete/stage.hpp"
#include "relpos/core/registry.hpp"

namespace relpos::complete {

// options: how the stage may spend its time (stage.hpp); copied, the caller need not keep it.
// replace: take the place of a numeric stage already registered (e.g. registerBuiltins's, to
// change its options) instead of throwing std::invalid_argument.
void registerStage(Registry& registry, const StageOptions& options = StageOptions(),
                   bool replace = false);

}  // namespace relpos::complete
