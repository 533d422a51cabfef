#include "relpos/complete/register.hpp"

#include "relpos/complete/stage.hpp"

namespace relpos::complete {
namespace {

bool answer(const Problem& problem, const Registry& registry, const Tolerance& tol,
            Solution& solution, const void* context) {
  return solveComplete(problem, registry, tol, solution, nullptr,
                       *static_cast<const StageOptions*>(context));
}

}  // namespace

void registerStage(Registry& registry, const StageOptions& options, bool replace) {
  // The registry keeps the options (and its copies share them) for the callbacks' context.
  registry.setFallback({"complete", &answer, registry.keep(options)}, replace);
}

}  // namespace relpos::complete
