#include "relpos/rules/builtin.hpp"

#include "relpos/manifolds/builtin.hpp"

namespace relpos::rules {
void registerBuiltinRules(Registry& r) {
  // Pinned-point rules first: they decide every pair that has a point-point coincidence.
  registerPinnedPointRules(r);
  registerPointPointRules(r);
  registerPointPointLineRules(r);
  registerPointLineRules(r);
  registerPointPointPlaneRules(r);
  registerPointLinePlaneRules(r);
  registerPointPlaneRules(r);
  registerMixedRoleRules(r);
  registerAngleRules(r);
  registerRangeRules(r);
  registerRangeCutRules(r);
}
}  // namespace relpos::rules

namespace relpos {
void registerBuiltins(Registry& r) {
  rules::registerBuiltinConstraintTypes(r);
  rules::registerBuiltinRules(r);
  manifolds::registerBuiltinManifolds(r);
  manifolds::registerMixedManifolds(r);
}

const Registry& builtinRegistry() {
  static const Registry registry = [] {
    Registry r;
    registerBuiltins(r);
    r.freeze();
    return r;
  }();
  return registry;
}
}  // namespace relpos
