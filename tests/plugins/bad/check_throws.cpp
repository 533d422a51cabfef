// A constraint type whose value check throws: the spec reader reports it as the constraint's
// problem naming this plugin, and so does a solve of a problem built in code.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace check_throws {
using namespace relpos;

void checkThrows(const InputConstraint&, std::vector<std::string>&, const void*) {
  throw std::runtime_error("the value check blew up");
}
void decomposeNothing(const InputConstraint&, const Feature&, SourceMask, Decomposition& out,
                      const void*) {
  out.unhandled = "never reached: the check throws first";
}

void registerAll(Registry& registry) {
  ConstraintType t;
  t.name = "explodes-in-check";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.check = &checkThrows;
  t.decompose = &decomposeNothing;
  registry.addConstraintType(t);
}
}  // namespace check_throws

RELPOS_PLUGIN(check_throws::registerAll)
