#pragma once
// A JSON document as the mutator edits it: unlike a parsed JSON value it keeps what a parser
// would refuse or normalise away — duplicate keys, numbers spelled as written (1e400, NaN, -0),
// strings as the bytes between their quotes (escapes, invalid UTF-8, raw control characters) and
// verbatim text (a bracket nesting 10⁵ deep) — so that a mutated spec reaches the reader exactly
// as a hostile file would.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace relpos::fuzz {

struct JsonNode {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject, kRaw };
  Kind kind = Kind::kNull;
  // kBool: "true"/"false"; kNumber: its literal; kString: the text between the quotes, written
  // as is (escapes included); kRaw: written verbatim.
  std::string text;
  std::vector<std::string> keys;  // kObject: the keys (as kString text), parallel to `items`
  std::vector<JsonNode> items;    // kArray: the elements; kObject: the values

  static JsonNode null() { return {}; }
  static JsonNode boolean(bool v) { return {Kind::kBool, v ? "true" : "false", {}, {}}; }
  static JsonNode number(std::string literal) {
    return {Kind::kNumber, std::move(literal), {}, {}};
  }
  // A string whose quoted body is `body` (already escaped, or deliberately not).
  static JsonNode string(std::string body) { return {Kind::kString, std::move(body), {}, {}}; }
  static JsonNode raw(std::string text) { return {Kind::kRaw, std::move(text), {}, {}}; }
  static JsonNode array() { return {Kind::kArray, "", {}, {}}; }
  static JsonNode object() { return {Kind::kObject, "", {}, {}}; }

  // The value of the first member named `key` (nullptr when there is none or this is no object).
  JsonNode* member(const std::string& key);
  void set(const std::string& key, JsonNode value);  // replaces the first such member or appends
  void erase(const std::string& key);                // every member of that name
};

// A parsed document as a tree (numbers in nlohmann's shortest round-trip spelling).
JsonNode fromJson(const nlohmann::ordered_json& j);
// The body of a JSON string literal for `s` (escaped as JSON requires).
std::string escapedBody(const std::string& s);

// The text of the tree: compact on one line, or (`indent` > 0) over several lines, so that a
// malformed document's line and column are worth checking.
std::string serialize(const JsonNode& node, int indent = 0);

}  // namespace relpos::fuzz
