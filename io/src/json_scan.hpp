#pragma once
// Where a JSON text goes wrong, for the texts simdjson refuses (json_read.cpp).
//
// simdjson's DOM parser says *that* a text is malformed but not *where*. This scan walks the text
// once more along JSON's grammar (RFC 8259), without recursion (an explicit stack, so 10^5
// nested brackets are just a long walk), and stops at the first byte after which the text can no
// longer be the start of any valid JSON text: that byte's line and column are the error's. It
// runs only after simdjson has refused a text (or found it nested too deeply), so it costs
// nothing on the path of a valid spec.
//
// It also finds what simdjson refuses although it is valid JSON or is ours to report: numbers
// beyond a double's range (an error at their JSON path) and integers beyond 64 bits (valid JSON:
// json_read.cpp has simdjson read them as the doubles they are).
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "relpos/io/spec_reader.hpp"

namespace relpos::detail {

// At most this many arrays and objects inside each other (the document itself counts as one).
inline constexpr std::size_t kMaxJsonDepth = 1024;

struct JsonScan {
  // In text order: every number out of a double's range, then the first syntax error (or the
  // first container beyond kMaxJsonDepth), which ends the scan. Escaped for a one-line message.
  std::vector<Diagnostic> errors;
  // [begin, end) of every integer too wide for 64 bits (while no error was found).
  std::vector<std::pair<std::size_t, std::size_t>> wide_integers;
};

JsonScan scanJson(std::string_view text);

// Whether `token` is a number in JSON's grammar; `integral`: without fraction and exponent.
bool isJsonNumber(std::string_view token, bool* integral);

// The double a JSON number token denotes, correctly rounded (±inf beyond a double's range).
double jsonNumberValue(std::string_view token);

}  // namespace relpos::detail
