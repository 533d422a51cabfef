#include "known_failures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <cstring>

namespace relpos::fuzz {
namespace {

bool strict() {
  static const bool s = [] {
    const char* v = std::getenv("RELPOS_FUZZ_STRICT");
    return v && *v && std::strcmp(v, "0") != 0;
  }();
  return s;
}

bool contains(std::string_view s, std::string_view part) {
  return s.find(part) != std::string_view::npos;
}

const KnownFailure kNumberOverflow = {
    "number-overflow-without-path",
    "a number beyond double range (1e400) is 'malformed JSON: number overflow parsing ...': no "
    "JSON path, no line and column (issue 13; the simdjson reader, deliverable 2)"};

const KnownFailure kRootWithoutPath = {
    "root-error-without-path",
    "a document that is JSON but not an object ('[1]', '0') gives 'the spec must be a JSON "
    "object' with the empty path: no JSON path, no line and column"};

const KnownFailure kNulEndsDocument = {
    "nul-ends-the-document",
    "a NUL byte ends the document: whatever follows it is not read (nlohmann's lexer takes "
    "'\\0' for the end of input), so '{...valid spec...}\\0garbage' is solved"};

const KnownFailure kSquareOverflow = {
    "overflow-beyond-1e154",
    "a number beyond ~1e154 in magnitude overflows a squared norm (squaredNorm, norm): a huge "
    "direction becomes (0,0,0) and the 'solved' poses violate the constraints; a huge initial "
    "position makes the nearest distance infinite (written null, best null) (issue 13: 'scale "
    "before squaring', deliverable 5)"};

// Whether the text spells a finite number of magnitude 1e150 or more (digits, sign, point and
// exponent in a row, as JSON writes numbers).
bool holdsHugeNumber(std::string_view text) {
  auto numeric = [](char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
  };
  for (std::size_t i = 0; i < text.size();) {
    if (!numeric(text[i]) || text[i] == 'e' || text[i] == 'E') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && numeric(text[j])) ++j;
    const std::string literal(text.substr(i, j - i));
    const double v = std::strtod(literal.c_str(), nullptr);
    if (std::isfinite(v) && std::abs(v) >= 1e150) return true;
    i = j;
  }
  return false;
}

const KnownFailure kNewlineInDiagnostic = {
    "newline-in-diagnostic",
    "a Diagnostic's path or message quotes a name or key as decoded, a newline (an escaped \\n in "
    "the JSON) included: the library's diagnostics are not one line (the CLI escapes them when it "
    "prints them, so stderr stays one line per diagnostic)"};

const KnownFailure kEmptyKeyWithoutPath = {
    "empty-key-without-path",
    "an unknown member named \"\" at the top level is warned about with the empty path "
    "(\"FILE: unknown field (ignored) (warning)\"): the path of a key \"\" is spelled as nothing"};

const KnownFailure kDeepNesting = {
    "deep-nesting-stack-overflow",
    "a value nested 10^5 deep or more overflows the stack (SIGSEGV in nlohmann's recursive "
    "copy of the parsed value, parseSpecWithNlohmann): at 10^5 in some processes and not "
    "others (the stack left), always at 3x10^5 (issue 13, 'Crashes'; the simdjson reader bounds "
    "the depth)"};

// The deepest nesting of brackets and braces outside strings.
int nestingDepth(std::string_view text) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

const KnownFailure* knownFailure(const Finding& f, std::string_view input) {
  if (strict()) return nullptr;
  if ((f.kind == "wrong-answer" || f.kind == "bad-output" || f.kind == "bad-problem") &&
      holdsHugeNumber(input))
    return &kSquareOverflow;
  if (f.kind == "split-diagnostic") return &kNewlineInDiagnostic;
  if ((f.kind == "crash" || f.kind == "hang") && nestingDepth(input) >= 100000)
    return &kDeepNesting;
  if (f.kind == "pathless-message" && contains(f.detail, "no JSON path: '': 'unknown field (ignored)'"))
    return &kEmptyKeyWithoutPath;
  if (f.kind == "pathless-message" && contains(f.detail, "number overflow parsing"))
    return &kNumberOverflow;
  if (f.kind == "pathless-message" && contains(f.detail, "'the spec must be a JSON object'"))
    return &kRootWithoutPath;
  if (f.kind == "accepted-invalid-json" && contains(f.detail, "raw byte \\x00"))
    return &kNulEndsDocument;
  return nullptr;
}

}  // namespace relpos::fuzz
