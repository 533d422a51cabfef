#pragma once
// A JSON text read into simdjson's DOM (a private header of relpos_core: no simdjson type
// reaches the public headers), with relpos's diagnostics for a text that cannot be read:
//   - malformed JSON (invalid UTF-8 included): "malformed JSON at line L, column C: what";
//   - nesting beyond simdjson's limit: "too deeply nested at line L, column C: ...";
//   - a number beyond a double's range: an error at its JSON path, with line and column.
// Integers beyond 64 bits, which simdjson 3.0 refuses, are valid JSON and read as the doubles
// strtod gives them. Keys twice in an object and relpos's own depth limit are checkKeys's: the
// spec checks see most objects anyway and run it only where they do not look (spec_parse.cpp).
#include <simdjson.h>

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relpos/io/spec_reader.hpp"

namespace relpos::detail {

struct JsonRead {
  std::optional<simdjson::dom::element> root;  // the document, when it could be read
  std::vector<Diagnostic> errors;              // why not
};

// The document lives in the calling thread's parser: it is valid until that thread's next
// readJson (a parser reused per thread keeps its buffers: no allocation per spec).
JsonRead readJson(std::string_view text);

// Every key that appears twice in one object within `value` (the value at `value_path`, inside
// `depth_above` arrays and objects): an error at its path, found in linear time. False when the
// value nests deeper than kMaxJsonDepth counted from the document (errors are then incomplete:
// tooDeep says where).
bool checkKeys(simdjson::dom::element value, const std::string& value_path, std::size_t depth_above,
               std::vector<Diagnostic>* errors);

// The error for a text that simdjson read but that nests deeper than kMaxJsonDepth.
std::vector<Diagnostic> tooDeep(std::string_view text);

}  // namespace relpos::detail
