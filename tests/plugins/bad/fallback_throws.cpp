// A numeric stage that throws on every problem it is handed (only those the rules leave
// `unhandled`): the rules' answer must stand, naming the plugin.
#include <stdexcept>

#include "relpos/core/plugin_api.hpp"

namespace fallback_throws {
using namespace relpos;

bool answerThrows(const Problem&, const Registry&, const Tolerance&, Solution&, const void*) {
  throw std::runtime_error("the fallback blew up");
}

void registerAll(Registry& registry) {
  // (replace: relpos may register a numeric stage of its own; this test needs its own to run)
  registry.setFallback({"explodes-in-fallback", &answerThrows}, /*replace=*/true);
}
}  // namespace fallback_throws

RELPOS_PLUGIN(fallback_throws::registerAll)
