// Constraint types whose decomposition throws: a std::exception, and something that is not one.
// The solve must answer `unhandled` naming this plugin, never abort or exit 1.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace decompose_throws {
using namespace relpos;

void decomposeThrows(const InputConstraint&, const Feature&, SourceMask, Decomposition&,
                     const void*) {
  throw std::runtime_error("the decomposition blew up");
}
void decomposeThrowsAnInt(const InputConstraint&, const Feature&, SourceMask, Decomposition&,
                          const void*) {
  throw 42;
}

void registerAll(Registry& registry) {
  ConstraintType t;
  t.name = "explodes-in-decomposition";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.decompose = &decomposeThrows;
  registry.addConstraintType(t);
  t.name = "throws-an-int";
  t.decompose = &decomposeThrowsAnInt;
  registry.addConstraintType(t);
}
}  // namespace decompose_throws

RELPOS_PLUGIN(decompose_throws::registerAll)
