#pragma once
// The scene a page shows, as the JSON its script reads (viewer/web/src/main.js).
#include <nlohmann/json.hpp>
#include <vector>

#include "relpos/viewer/page.hpp"

namespace relpos::viewer::detail {

// False with the problems in *errors when a mesh cannot be read.
bool sceneJson(const Problem& problem, const Solution& solution, const Report& report,
               const ViewOptions& options, nlohmann::json* scene, std::vector<Diagnostic>* errors,
               std::vector<Diagnostic>* warnings);

}  // namespace relpos::viewer::detail
