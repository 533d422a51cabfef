#include "relpos/complete/register.hpp"

#include "relpos/complete/stage.hpp"

namespace relpos::complete {
namespace {

bool answer(const Problem& problem, const Registry& registry, const Tolerance& tol,
            Solution& solution, const void* context) {
  return solveComplete(problem, registry, tol, solution, nullptr,
                       *static_cast<const StageOptions*>(context));
}

// The registry holds a context pointer, not a copy: every distinct options value lives here for
// the program's life.
const StageOptions* kept(const StageOptions& options) {
  static const StageOptions computing{true}, stored_only{false};
  return options.compute_start_systems ? &computing : &stored_only;
}

}  // namespace

void registerStage(Registry& registry, const StageOptions& options, bool replace) {
  registry.setFallback({"complete", &answer, kept(options)}, replace);
}

}  // namespace relpos::complete
