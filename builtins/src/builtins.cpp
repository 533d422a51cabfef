#include "relpos/builtins/builtins.hpp"

#include "relpos/complete/register.hpp"
#include "relpos/manifolds/builtin.hpp"
#include "relpos/rules/builtin.hpp"

namespace relpos {

void registerBuiltins(Registry& r) {
  rules::registerBuiltinConstraintTypes(r);
  rules::registerBuiltinRules(r);
  manifolds::registerBuiltinManifolds(r);
  manifolds::registerMixedManifolds(r);
  complete::registerStage(r);
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
