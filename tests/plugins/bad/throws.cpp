// A plugin that registers one constraint type, then throws: the loader must report it and leave
// the registry as it was (the half-registered type gone).
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace throws_plugin {
void registerAll(relpos::Registry& registry) {
  relpos::ConstraintType t;
  t.name = "half-registered";
  t.accepts = {{relpos::FeatureKind::kPoint, relpos::FeatureKind::kPoint}};
  registry.addConstraintType(t);
  throw std::runtime_error("the plugin's own set-up failed");
}
}  // namespace throws_plugin

RELPOS_PLUGIN(throws_plugin::registerAll)
