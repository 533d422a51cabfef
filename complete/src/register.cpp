#include "relpos/complete/register.hpp"

#include "relpos/complete/stage.hpp"

namespace relpos::complete {
namespace {

bool answer(const Problem& problem, const Registry& registry, const Tolerance& tol,
            Solution& solution, const void* /*context*/) {
  return solveComplete(problem, registry, tol, solution);
}

}  // namespace

void registerStage(Registry& registry) { registry.setFallback({"complete", &answer, nullptr}); }

}  // namespace relpos::complete
