// A plugin whose constraint type throws while it is decomposed: what any plugin (or library) bug
// looks like from inside a solve. A batch must turn it into that spec's result line and go on.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace throwing_plugin {

void decomposeExplodes(const relpos::InputConstraint&, const relpos::Feature&, relpos::SourceMask,
                       relpos::Decomposition&, const void*) {
  throw std::runtime_error("explodes: this decomposition gives up on purpose");
}

void registerAll(relpos::Registry& registry) {
  relpos::ConstraintType t;
  t.name = "explodes";
  t.description = "point(f)-point(m): throws when decomposed (a test of the host's guard)";
  t.accepts = {{relpos::FeatureKind::kPoint, relpos::FeatureKind::kPoint}};
  t.decompose = &decomposeExplodes;
  registry.addConstraintType(t);
}

}  // namespace throwing_plugin

RELPOS_PLUGIN(throwing_plugin::registerAll)
