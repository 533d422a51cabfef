// A manifold matcher that throws on the sets of its own fundamental kind (the type
// `explodes-in-matcher`); the built-in matchers pass on those, so only that type reaches it.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace matcher_throws {
using namespace relpos;

std::uint16_t g_kind = 0;

double residual(const Fundamental&, const Isometry3d&) { return 0.0; }

void decompose(const InputConstraint&, const Feature&, SourceMask s, Decomposition& out) {
  Fundamental f;
  f.kind = FundamentalKind::kCustom;
  f.custom = g_kind;
  f.sources = s;
  out.addAlternative().push_back(f);
}

MatchResult matchThrows(MatchContext& ctx) {
  for (const Fundamental& f : ctx.set.translational)
    if (f.kind == FundamentalKind::kCustom && f.custom == g_kind)
      throw std::runtime_error("the matcher blew up");
  return MatchResult::kNoMatch;
}

void registerAll(Registry& registry) {
  g_kind = registry.addCustomKind({"matcher-bait", "the throwing matcher's kind", &residual});
  ConstraintType t;
  t.name = "explodes-in-matcher";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.decompose = &decompose;
  registry.addConstraintType(t);
  registry.addMatcher({"explodes", &matchThrows});
}
}  // namespace matcher_throws

RELPOS_PLUGIN(matcher_throws::registerAll)
