#include "safe_text.hpp"

#include <cstdint>
#include <cstring>

namespace relpos::cli {
namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// The length of the valid UTF-8 sequence that starts at s[i], 0 when none does.
std::size_t sequenceAt(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned c = byte(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // the range of the second byte (Table 3-7)
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;  // no overlong forms
    if (c == 0xED) hi = 0x9F;  // no surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;  // no overlong forms
    if (c == 0xF4) hi = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (s.size() - i < n || byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return n;
}

// Whether the 8 bytes at p are all ASCII (the common case, checked a word at a time).
bool asciiWord(const char* p) {
  std::uint64_t w;
  std::memcpy(&w, p, sizeof w);
  return (w & 0x8080808080808080ull) == 0;
}

// Calls ascii(i, n) for each run of ASCII bytes, valid(i, n) for each valid multi-byte sequence
// and invalid(i) for each byte that belongs to none.
template <typename Ascii, typename Valid, typename Invalid>
void scan(std::string_view s, Ascii ascii, Valid valid, Invalid invalid) {
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t j = i;
    while (j + 8 <= s.size() && asciiWord(s.data() + j)) j += 8;
    while (j < s.size() && static_cast<unsigned char>(s[j]) < 0x80) ++j;
    if (j > i) ascii(i, j - i);
    if (j == s.size()) return;
    const std::size_t n = sequenceAt(s, j);
    if (n == 0) {
      invalid(j);
      i = j + 1;
    } else {
      valid(j, n);
      i = j + n;
    }
  }
}

}  // namespace

bool isValidUtf8(std::string_view s) {
  bool ok = true;
  scan(
      s, [](std::size_t, std::size_t) {}, [](std::size_t, std::size_t) {},
      [&](std::size_t) { ok = false; });
  return ok;
}

std::string validUtf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  const auto copy = [&](std::size_t i, std::size_t n) { out.append(s.data() + i, n); };
  scan(s, copy, copy, [&](std::size_t) { out += kReplacement; });
  return out;
}

std::string oneLine(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  const auto ascii = [&](std::size_t i, std::size_t n) {
    for (const char c : s.substr(i, n)) {
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x20 && u != 0x7F) {
        out += c;
      } else if (c == '\n') {
        out += "\\n";
      } else if (c == '\r') {
        out += "\\r";
      } else if (c == '\t') {
        out += "\\t";
      } else {
        static constexpr char kHex[] = "0123456789ABCDEF";
        out += "\\x";
        out += kHex[u >> 4];
        out += kHex[u & 0xF];
      }
    }
  };
  scan(
      s, ascii, [&](std::size_t i, std::size_t n) { out.append(s.data() + i, n); },
      [&](std::size_t) { out += kReplacement; });
  return out;
}

void appendJsonString(std::string& out, std::string_view s) {
  out += '"';
  const auto ascii = [&](std::size_t i, std::size_t n) {
    for (const char c : s.substr(i, n)) {
      const auto u = static_cast<unsigned char>(c);
      switch (c) {
        case '"':
          out += "\\\"";
          break;
        case '\\':
          out += "\\\\";
          break;
        case '\b':
          out += "\\b";
          break;
        case '\f':
          out += "\\f";
          break;
        case '\n':
          out += "\\n";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\t':
          out += "\\t";
          break;
        default:
          if (u < 0x20) {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\u00";
            out += kHex[u >> 4];
            out += kHex[u & 0xF];
          } else {
            out += c;
          }
      }
    }
  };
  scan(
      s, ascii, [&](std::size_t i, std::size_t n) { out.append(s.data() + i, n); },
      [&](std::size_t) { out += kReplacement; });
  out += '"';
}

}  // namespace relpos::cli
