#include "utf8.hpp"

#include <cstdio>

namespace relpos::detail {

std::string toValidUtf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const Utf8Step step = utf8Step(s.substr(i));
    if (step.valid)
      out.append(s.data() + i, step.length);
    else
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
    i += step.length;
  }
  return out;
}

namespace {

// Whether a well-formed sequence must be escaped: it would break the line (or is invisible
// control) on a terminal or in a log.
bool needsEscape(std::string_view seq) {
  const auto c = static_cast<unsigned char>(seq[0]);
  if (seq.size() == 1) return c < 0x20 || c == 0x7F;
  if (c == 0xC2) return static_cast<unsigned char>(seq[1]) < 0xA0;  // C1 controls U+0080..U+009F
  // U+2028 LINE SEPARATOR, U+2029 PARAGRAPH SEPARATOR
  return seq.size() == 3 && c == 0xE2 && seq[1] == '\x80' && (seq[2] == '\xA8' || seq[2] == '\xA9');
}

void appendEscaped(std::string& out, std::string_view seq) {
  char buf[8];
  if (seq.size() == 1) {
    switch (seq[0]) {
      case '\n':
        out += "\\n";
        return;
      case '\r':
        out += "\\r";
        return;
      case '\t':
        out += "\\t";
        return;
      case '\0':
        out += "\\0";
        return;
      default:
        std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned char>(seq[0]));
        out += buf;
        return;
    }
  }
  // Decode the 2- or 3-byte sequence to its code point.
  const auto b0 = static_cast<unsigned char>(seq[0]), b1 = static_cast<unsigned char>(seq[1]);
  const unsigned cp = seq.size() == 2 ? ((b0 & 0x1Fu) << 6) | (b1 & 0x3Fu)
                                      : ((b0 & 0x0Fu) << 12) | ((b1 & 0x3Fu) << 6) |
                                            (static_cast<unsigned char>(seq[2]) & 0x3Fu);
  std::snprintf(buf, sizeof buf, "\\u%04X", cp);
  out += buf;
}

}  // namespace

std::string escapeForMessage(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const Utf8Step step = utf8Step(s.substr(i));
    const std::string_view seq = s.substr(i, step.length);
    if (!step.valid) {
      for (char byte : seq) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned char>(byte));
        out += buf;
      }
    } else if (needsEscape(seq)) {
      appendEscaped(out, seq);
    } else {
      out += seq;
    }
    i += step.length;
  }
  return out;
}

}  // namespace relpos::detail
