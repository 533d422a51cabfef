#pragma once
// What an engineer can change when the rules leave a combined set unmatched (issue 16,
// docs/spec.md §2.2): the input constraints the set came from, named by index and id with their
// values in the spec's units, and a hint for the pattern they form.
#include <string>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"

namespace relpos::detail {

// "of 2 'work angle' (angle floor–axis, 35° to 55°) and 3 'travel angle' (…). HINT"
std::string explainUnmatched(const Problem& problem, const Registry& registry,
                             SourceMask involved);

}  // namespace relpos::detail
