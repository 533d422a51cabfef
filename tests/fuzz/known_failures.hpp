#pragma once
// Failures the checks find on the current code that are already reported and owned elsewhere
// (issue 13; see /work/wt/notes/fuzz-report.md and tests/fuzz/regressions/). A finding that
// matches one is counted under its id instead of failing the run, so that the fuzzer, the
// mutation test and the campaign go on looking for new ones. The checks themselves are not
// weakened: RELPOS_FUZZ_STRICT=1 in the environment turns every known failure back into a
// failure, and an entry is deleted once its fix is merged.
#include <string_view>

#include "result_checks.hpp"

namespace relpos::fuzz {

struct KnownFailure {
  const char* id;    // short name, e.g. "number-overflow-without-path"
  const char* what;  // the bug, for the summary
};

// The known failure this finding on this input is, or nullptr (also always with
// RELPOS_FUZZ_STRICT=1).
const KnownFailure* knownFailure(const Finding& f, std::string_view input);

}  // namespace relpos::fuzz
