#pragma once
// Checks bundled specs against their hand-derived expectations (data/expected/*.json): status,
// branch count, DOF per branch, conflicts, redundant constraints, an optional rule case that must
// fire, and every sampled pose of every branch against every input constraint.
#include <string>

#include "relpos/core/registry.hpp"

namespace relpos::test {

// Solves every spec in data/<folder> and checks it against data/expected/<expected_file>;
// returns how many specs were checked (each expectation must have its spec). Specs are parsed and
// solved with `registry` (the built-ins unless given, e.g. one with plugins loaded).
int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file,
                                   const Registry& registry);
int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file);

}  // namespace relpos::test
