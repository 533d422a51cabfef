#pragma once
// Every built-in manifold type, as the registry lists them (Registry::manifolds()): what was built
// in is what is listed. The rotation and translation shapes of separable branches come from the
// variants that hold them (rotation/shapes.hpp, translation/shapes.hpp), as "rotation/NAME" and
// "translation/NAME" with NAME the one results write; shapes that write the same name (a line of
// two planes is a "Line") share one entry, their summaries joined by "; ". The mixed manifolds are
// one line each in catalogue.cpp, as "mixed/TYPENAME".
#include <vector>

#include "relpos/core/registry.hpp"

namespace relpos::manifolds {

std::vector<ManifoldInfo> separableShapeCatalogue();
std::vector<ManifoldInfo> mixedManifoldCatalogue();
// Both, in the order registerBuiltinManifolds and registerMixedManifolds register them.
std::vector<ManifoldInfo> builtinManifoldCatalogue();

}  // namespace relpos::manifolds
