#pragma once
// Writing results (docs/spec.md §2): a Report (relpos/io/report.hpp, computed by relpos::evaluate
// in report/) as JSON text. The one writer of every result field: a new field is written here only.
// Never throws on a Report's contents: strings are escaped as JSON needs and always valid UTF-8
// (ill-formed bytes become U+FFFD), non-finite numbers are null.
#include <string>

#include "relpos/io/report.hpp"

namespace relpos {

struct ResultFormat {
  // One line (relpos batch), or indented by two spaces (relpos solve's document).
  bool indented = false;
  // How numbers are spelled; both read back as exactly the same double.
  //   false: the shortest text (std::to_chars), with ".0" on integral values — the batch line.
  //   true:  as the nlohmann JSON library prints them (fixed notation for decimal exponents in
  //          (-5, 15], Grisu2 digits) — the documents relpos printed through that library before
  //          it had its own writer (solve's, and batch lines with collision fields), kept
  //          byte-identical.
  bool library_numbers = false;
  // Angles in degrees (`--angles deg`, docs/spec.md §2.5, since issue 17): angle parameters'
  // values and bounds, rotation rates and pitches, a certificate's angle; the document then
  // says "units": {"angle": "deg"}. Orientations stay quaternions, `distance` the metric.
  bool degrees = false;
};
inline constexpr ResultFormat kResultLine{false, false};
inline constexpr ResultFormat kCollisionLine{false, true};
inline constexpr ResultFormat kResultDocument{true, true};

// The result document of `report` into `out`, replacing its contents (`out` is reused: a batch
// keeps one per thread, and after the first lines writing allocates nothing).
void writeReport(const Report& report, ResultFormat format, std::string& out);

// A result without branches, {"relpos":1,"name":…,"status":…,"message":…}: a batch's invalid
// line, or one whose spec threw.
void writeStatusLine(const std::string& name, const char* status, const std::string& message,
                     std::string& out);

}  // namespace relpos
