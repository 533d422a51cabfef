#pragma once
// Input constraints as the messages name them (docs/spec.md §2.2): by index and id, type,
// features and value or range in the spec's units — "2 'work angle' (angle floor–axis, 35° to
// 55°)" — so that an engineer can find the one to change.
#include <cstddef>
#include <string>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"

namespace relpos {

std::string describeConstraint(const Problem& problem, const Registry& registry, std::size_t i);

// Those of `which` (bit i: constraint i; from 64 on not named), "a, b and c".
std::string describeConstraints(const Problem& problem, const Registry& registry,
                                SourceMask which);

}  // namespace relpos
