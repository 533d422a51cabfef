#include "known_failures.hpp"

namespace relpos::fuzz {

const KnownFailure* knownFailure(const Finding& f, std::string_view input) {
  // None at present: the last two (an initial pose beyond 1e100 whose nearest distances were
  // infinite, a problem 1e15 from the origin solved although infeasible) are fixed, and their
  // regressions fail as any other finding would. A new entry is a `const KnownFailure` matched
  // here, narrowly, on the finding's kind and detail and on the input (RELPOS_FUZZ_STRICT=1 in the
  // environment must still turn it back into a failure).
  (void)f;
  (void)input;
  return nullptr;
}

}  // namespace relpos::fuzz
