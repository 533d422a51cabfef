#pragma once
// What the io tests share: a spec read from text with the built-in types, and doubles compared
// bit for bit (a number must read back exactly as written, not merely close).
#include <cstring>
#include <string>

#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"

namespace relpos::test {

inline ParseResult parse(const std::string& text) {
  return parseSpec(text, builtinRegistry(), "t");
}

inline bool sameDouble(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace relpos::test
