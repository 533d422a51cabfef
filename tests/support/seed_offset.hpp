#pragma once
// RELPOS_PROPERTY_SEED_OFFSET: moves every seed of the property tests, to hunt beyond the cases CI
// runs (`RELPOS_PROPERTY_SEED_OFFSET=17 build/tests/property_tests`); unset or unreadable, 0 — the
// cases CI runs.
#include <cstdint>
#include <cstdlib>

namespace relpos::test {

inline std::uint64_t propertySeedOffset() {
  const char* s = std::getenv("RELPOS_PROPERTY_SEED_OFFSET");
  return s ? std::strtoull(s, nullptr, 10) : 0;
}

}  // namespace relpos::test
