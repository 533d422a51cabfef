// A combination rule that throws. The type `explodes-in-rule` decomposes into two fundamentals of
// this plugin's own kind, and the plugin's rule for that pair throws: only problems using the
// type reach it.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace rule_throws {
using namespace relpos;

std::uint16_t g_kind = 0;

double residual(const Fundamental&, const Isometry3d&) { return 0.0; }

void decompose(const InputConstraint&, const Feature&, SourceMask s, Decomposition& out) {
  auto& alt = out.addAlternative();
  Fundamental f;
  f.kind = FundamentalKind::kCustom;
  f.custom = g_kind;
  f.sources = s;
  alt.push_back(f);
  alt.push_back(f);
}

void ruleThrows(const Fundamental& a, const Fundamental& b, const Tolerance&, RuleOutput&,
                const void*) {
  if (a.custom == g_kind && b.custom == g_kind) throw std::runtime_error("the rule blew up");
}

void registerAll(Registry& registry) {
  g_kind = registry.addCustomKind({"rule-bait", "two of these meet the throwing rule", &residual});
  ConstraintType t;
  t.name = "explodes-in-rule";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.decompose = &decompose;
  registry.addConstraintType(t);
  RuleInfo r;
  r.name = "explodes:custom+custom";
  r.first = r.second = FundamentalKind::kCustom;
  r.fn = &ruleThrows;
  registry.addRule(r);
}
}  // namespace rule_throws

RELPOS_PLUGIN(rule_throws::registerAll)
