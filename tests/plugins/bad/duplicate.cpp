// A plugin that registers a constraint type under a built-in's name ("distance"): refused unless
// an override is asked for, then it replaces the built-in.
#include "relpos/core/plugin_api.hpp"

namespace duplicate_plugin {
void decompose(const relpos::InputConstraint&, const relpos::Feature&, relpos::SourceMask,
               relpos::Decomposition& out, const void*) {
  out.unhandled = "the duplicate plugin's distance decomposes nothing";
}
void registerAll(relpos::Registry& registry) {
  relpos::ConstraintType t;
  t.name = "distance";
  t.description = "a plugin's replacement";
  t.accepts = {{relpos::FeatureKind::kPoint, relpos::FeatureKind::kPoint}};
  t.takes_value = true;
  t.decompose = &decompose;
  registry.addConstraintType(t);
}
}  // namespace duplicate_plugin

RELPOS_PLUGIN(duplicate_plugin::registerAll)
