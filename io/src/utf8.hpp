#pragma once
// UTF-8 well-formedness, one sequence at a time (Unicode 15, table 3-7), for the three places
// relpos echoes text it did not write: diagnostics (escaped, one line), result lines (always valid
// UTF-8: ill-formed bytes become U+FFFD) and the JSON scan's line/column counts.
#include <cstddef>
#include <string>
#include <string_view>

namespace relpos::detail {

struct Utf8Step {
  std::size_t length;  // bytes of the sequence, or of the maximal ill-formed subpart (≥ 1)
  bool valid;
};

// The sequence starting at s[0] (s not empty). An ill-formed one is reported with the length of
// its "maximal subpart" (the lead byte and the continuation bytes that could still have followed
// it), so replacing each such subpart by one U+FFFD is the substitution Unicode recommends.
inline Utf8Step utf8Step(std::string_view s) {
  const auto c = static_cast<unsigned char>(s[0]);
  if (c < 0x80) return {1, true};
  std::size_t length;
  unsigned char lo = 0x80, hi = 0xBF;  // the second byte's range; later bytes are 80..BF
  if (c >= 0xC2 && c <= 0xDF) {
    length = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    length = 3;
    if (c == 0xE0) lo = 0xA0;  // no overlong forms
    if (c == 0xED) hi = 0x9F;  // no surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    length = 4;
    if (c == 0xF0) lo = 0x90;  // no overlong forms
    if (c == 0xF4) hi = 0x8F;  // nothing beyond U+10FFFF
  } else {
    return {1, false};  // a continuation byte, C0, C1 or F5..FF
  }
  for (std::size_t k = 1; k < length; ++k) {
    if (k >= s.size()) return {k, false};
    const auto b = static_cast<unsigned char>(s[k]);
    if (b < lo || b > hi) return {k, false};
    lo = 0x80, hi = 0xBF;
  }
  return {length, true};
}

// The text with every ill-formed UTF-8 subpart replaced by U+FFFD (the text itself when valid).
std::string toValidUtf8(std::string_view s);

// The text on one line and in valid UTF-8, for a diagnostic: \n \r \t \0, \xHH for other C0
// controls, DEL and each byte of an ill-formed sequence, \uHHHH for C1 controls and the Unicode
// line and paragraph separators. A backslash is left alone, so escaping twice changes nothing.
std::string escapeForMessage(std::string_view s);

}  // namespace relpos::detail
