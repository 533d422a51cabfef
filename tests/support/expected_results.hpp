#pragma once
// Checks bundled specs against their hand-derived expectations (data/expected/*.json, or one
// SPEC.expected beside each spec of data/rules): status, branch count, DOF per branch, conflicts,
// redundant constraints, an optional rule case that must fire, and every sampled pose of every
// branch against every input constraint.
#include <string>

#include "relpos/core/registry.hpp"

namespace relpos::test {

// Solves every spec in data/<folder> and checks it against data/expected/<expected_file>;
// returns how many specs were checked (each expectation must have its spec). Specs are parsed and
// solved with `registry` (the built-ins unless given, e.g. one with plugins loaded).
int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file,
                                   const Registry& registry);
int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file);

// Solves the spec at `spec_path` with `registry` and checks it against the expectation (one JSON
// object, as in data/expected/*.json) in the file `expected_path`.
void checkSpecAgainstExpectation(const std::string& spec_path, const std::string& expected_path,
                                 const Registry& registry);

}  // namespace relpos::test
