#pragma once
// What the slowest suites need to know about the build they run in: under AddressSanitizer a
// start system (monodromy, docs/spec.md §8.5) takes many times longer, and CI runs the whole
// suite again there (.ci/run) within its time budget.
#include <cstdlib>

namespace relpos::test {

inline constexpr bool kSanitizedBuild =
#if defined(__SANITIZE_ADDRESS__)
    true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    true;
#else
    false;
#endif
#else
    false;
#endif

// A sweep's case count in this build: a quarter under sanitizers (at least 1). They look for memory
// and undefined-behaviour errors on the code's paths, which a quarter of a sweep already takes;
// the sweeps' numbers are covered in full by the release build (CI's first run), and the whole
// suite again under ASan has to fit CI's 40 minutes.
constexpr int sweepCount(int n) { return kSanitizedBuild ? (n >= 4 ? n / 4 : 1) : n; }

// RELPOS_SLOW_TESTS=1 runs the suites that take minutes (by hand; not in CI).
inline bool slowTestsWanted() {
  const char* v = std::getenv("RELPOS_SLOW_TESTS");
  return v && *v && *v != '0';
}

}  // namespace relpos::test
