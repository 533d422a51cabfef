#pragma once
#include "relpos/core/registry.hpp"

namespace relpos::rules {
// Constraint types of SPEC.md §1 with their decomposition (PMF Table I).
void registerBuiltinConstraintTypes(Registry& registry);
// Combination rules, one function per PMF Appendix IV family.
void registerPinnedPointRules(Registry& registry);      // App. IV rows with p = 0, generalised
void registerPointPointRules(Registry& registry);       // App. IV Table I
void registerPointPointLineRules(Registry& registry);   // App. IV Table II
void registerPointLineRules(Registry& registry);        // App. IV Tables III and IV
void registerPointPointPlaneRules(Registry& registry);  // App. IV Table V
void registerPointLinePlaneRules(Registry& registry);   // App. IV Table VI
void registerPointPlaneRules(Registry& registry);       // App. IV Table VII
void registerMixedRoleRules(Registry& registry);        // App. IV Tables VIII and IX
void registerAngleRules(Registry& registry);            // App. IV Table X
void registerRangeRules(Registry& registry);            // Somani 004 Table VII (ranges)
void registerRangeCutRules(Registry& registry);  // Somani 004 Table VII (range with exact)
// Everything above.
void registerBuiltinRules(Registry& registry);
}  // namespace relpos::rules

namespace relpos {
// Registers every built-in constraint type, rule and manifold, then returns. Does not freeze.
void registerBuiltins(Registry& registry);
// One frozen registry holding the built-ins, made on first use (tests, benchmarks, tools).
const Registry& builtinRegistry();
}  // namespace relpos
