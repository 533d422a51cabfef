#pragma once
#include <string>
#include <vector>

#include "relpos/core/registry.hpp"

namespace relpos::rules {
// Constraint types of docs/spec.md §1 with their decomposition (PMF Table I).
void registerBuiltinConstraintTypes(Registry& registry);
// The combination rules, one family per PMF Appendix IV table (and Somani 004 Table VII for
// ranges), in the order of rules/src/families.def: that order decides which rule a pair meets
// first.
void registerBuiltinRules(Registry& registry);
// The id of each built-in family in rules/src/families.def (also its source file, rules/src/ID.cpp,
// and the prefix of its data specs, data/rules/ID--CASE.json), in registration order.
std::vector<std::string> builtinFamilyIds();
// A rule family or case name as files spell it: '+' and ':' become '_', '/' becomes "--"
// ("pp+pplane" → "pp_pplane", "pp+pplane/circle" → "pp_pplane--circle", "range:pp+pp" →
// "range_pp_pp").
std::string fileSpelling(const std::string& rule_name);
}  // namespace relpos::rules
