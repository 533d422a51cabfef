#include "relpos/rules/builtin.hpp"

#include "relpos/manifolds/builtin.hpp"

namespace relpos::rules {
void registerBuiltinRules(Registry& r) {
  registerPointPointRules(r);
  registerPinnedPointRules(r);
  registerPointLineRules(r);
  registerPointPlaneRules(r);
  registerAngleRules(r);
}
}  // namespace relpos::rules

namespace relpos {
void registerBuiltins(Registry& r) {
  rules::registerBuiltinConstraintTypes(r);
  rules::registerBuiltinRules(r);
  manifolds::registerBuiltinManifolds(r);
}
}  // namespace relpos
