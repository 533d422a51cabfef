#pragma once
// Reading specs (docs/spec.md §1). Bad input never throws out of these
// functions: every problem found becomes a Diagnostic naming the JSON path and what is wrong,
// on one line (control characters and ill-formed UTF-8 in echoed text are escaped).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "relpos/core/diagnostic.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"

namespace relpos {

struct ParseResult {
  std::optional<Problem> problem;  // set only when there are no errors
  std::vector<Diagnostic> errors;
  std::vector<Diagnostic> warnings;
  // The spec's "name" when it has a readable one, else the default name; also when the spec is
  // invalid (a batch's invalid line carries it). Valid UTF-8, like problem->name.
  std::string name;
};

// `default_name` is used when the spec has no "name" (the file name without extension); bytes of
// it that are not UTF-8 become U+FFFD.
ParseResult parseSpec(std::string_view text, const Registry& registry,
                      const std::string& default_name = "spec");
ParseResult parseSpecFile(const std::string& file, const Registry& registry);

// The spec's "plugins" list, each path resolved against the spec's folder: what to load before
// parsing it. Empty when there is none or the file cannot be read (parseSpecFile reports that).
std::vector<std::string> specPluginPaths(const std::string& file);
// The same for a spec given as text (a JSONL line), paths resolved against `dir`.
std::vector<std::string> specPluginPathsInText(std::string_view text, const std::string& dir);
// Whether the text contains the key "plugins" at all (a fast scan: when it does not, no spec in
// it has a plugin list).
bool mentionsPlugins(std::string_view text);

// "file: path: message" (path omitted when empty), on one line and in valid UTF-8 whatever the
// file name holds: \n \r \t \0, \xHH for other control bytes, DEL and bytes that are not UTF-8.
std::string formatDiagnostic(const std::string& file, const Diagnostic& d);

}  // namespace relpos
