#include "relpos/complete/register.hpp"

#include "relpos/complete/stage.hpp"

namespace relpos::complete {
namespace {

bool answer(const Problem& problem, const Registry& registry, const Tolerance& tol,
            Solution& solution, const void* context) {
  const auto& options = *static_cast<const StageOptions*>(context);
  if (solveComplete(problem, registry, tol, solution, nullptr, options)) return true;
  // What the polynomial stage does not take (ranges, sets of poses) or could not answer: charts.
  const std::string declined = solution.message;
  if (solveSets(problem, registry, tol, solution, options)) return true;
  solution.message = declined + "; " + solution.message;
  return false;
}

}  // namespace

void registerStage(Registry& registry, const StageOptions& options, bool replace) {
  // The registry keeps the options (and its copies share them) for the callbacks' context.
  registry.setFallback({"complete", &answer, registry.keep(options)}, replace);
}

}  // namespace relpos::complete
