// A manifold matcher that throws on the sets of its own fundamental kind (the type
// `explodes-in-matcher`); the built-in matchers pass on those, so only that type reaches it.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace matcher_throws {
using namespace relpos;

// The context of the callbacks: the registry's index of this plugin's kind.
std::uint16_t kindOf(const void* context) { return *static_cast<const std::uint16_t*>(context); }

double residual(const Fundamental&, const Isometry3d&, const void*) { return 0.0; }

void decompose(const InputConstraint&, const Feature&, SourceMask s, Decomposition& out,
               const void* context) {
  Fundamental f;
  f.kind = FundamentalKind::kCustom;
  f.custom = kindOf(context);
  f.sources = s;
  out.addAlternative().push_back(f);
}

MatchResult matchThrows(MatchContext& ctx, const void* context) {
  for (const Fundamental& f : ctx.set.translational)
    if (f.kind == FundamentalKind::kCustom && f.custom == kindOf(context))
      throw std::runtime_error("the matcher blew up");
  return MatchResult::kNoMatch;
}

void registerAll(Registry& registry) {
  const std::uint16_t* kind = registry.keep(
      registry.addCustomKind({"matcher-bait", "the throwing matcher's kind", &residual}));
  ConstraintType t;
  t.name = "explodes-in-matcher";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.decompose = &decompose;
  t.context = kind;
  registry.addConstraintType(t);
  registry.addMatcher({"explodes", &matchThrows, kind});
}
}  // namespace matcher_throws

RELPOS_PLUGIN(matcher_throws::registerAll)
