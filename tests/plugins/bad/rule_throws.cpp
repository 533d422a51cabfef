// A combination rule that throws. The type `explodes-in-rule` decomposes into two fundamentals of
// this plugin's own kind, and the plugin's rule for that pair throws: only problems using the
// type reach it (no other kind than this plugin's reaches the rule, registered for custom pairs).
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace rule_throws {
using namespace relpos;

double residual(const Fundamental&, const Isometry3d&, const void*) { return 0.0; }

// The context: the registry's index of this plugin's kind.
void decompose(const InputConstraint&, const Feature&, SourceMask s, Decomposition& out,
               const void* context) {
  auto& alt = out.addAlternative();
  Fundamental f;
  f.kind = FundamentalKind::kCustom;
  f.custom = *static_cast<const std::uint16_t*>(context);
  f.sources = s;
  alt.push_back(f);
  alt.push_back(f);
}

void ruleThrows(const Fundamental&, const Fundamental&, const Tolerance&, RuleOutput&,
                const void*) {
  throw std::runtime_error("the rule blew up");
}

void registerAll(Registry& registry) {
  ConstraintType t;
  t.name = "explodes-in-rule";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.decompose = &decompose;
  t.context = registry.keep(
      registry.addCustomKind({"rule-bait", "two of these meet the throwing rule", &residual}));
  registry.addConstraintType(t);
  RuleInfo r;
  r.name = "explodes:custom+custom";
  r.first = r.second = FundamentalKind::kCustom;
  r.fn = &ruleThrows;
  registry.addRule(r);
}
}  // namespace rule_throws

RELPOS_PLUGIN(rule_throws::registerAll)
