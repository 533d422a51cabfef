// The command's text helpers: whatever bytes come in, what goes out is UTF-8 (and one line, or
// one JSON string, where it must be).
#include "safe_text.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace relpos::cli {
namespace {

const std::string kFffd = "\xEF\xBF\xBD";

TEST(SafeText, ValidUtf8IsKeptAndEveryInvalidByteReplaced) {
  const std::string valid = "plain, \xC3\xA9, \xE2\x82\xAC, \xF0\x9F\x98\x80, \xF4\x8F\xBF\xBF";
  EXPECT_TRUE(isValidUtf8(valid));
  EXPECT_EQ(validUtf8(valid), valid);
  // Table 3-7's edges: overlong forms, surrogates, beyond U+10FFFF, stray continuation bytes,
  // sequences cut short (also at the very end).
  for (const std::string& bad :
       {std::string("\xC0\xAF"), std::string("\xE0\x80\xAF"), std::string("\xED\xA0\x80"),
        std::string("\xF4\x90\x80\x80"), std::string("\x80"), std::string("\xFF"),
        std::string("\xE2\x82"), std::string("\xF0\x9F\x98")}) {
    EXPECT_FALSE(isValidUtf8(bad)) << bad;
    const std::string fixed = validUtf8("a" + bad + "b");
    EXPECT_TRUE(isValidUtf8(fixed));
    EXPECT_EQ(
        fixed, "a" +
                   [&] {
                     std::string r;
                     for (std::size_t i = 0; i < bad.size(); ++i) r += kFffd;
                     return r;
                   }() +
                   "b")
        << bad;
  }
  // Long ASCII runs (checked eight bytes at a time) with a bad byte anywhere.
  for (std::size_t at = 0; at < 20; ++at) {
    std::string s(20, 'x');
    s[at] = '\xFF';
    EXPECT_FALSE(isValidUtf8(s)) << at;
    EXPECT_EQ(validUtf8(s), std::string(at, 'x') + kFffd + std::string(19 - at, 'x'));
  }
}

TEST(SafeText, OneLineEscapesControlCharacters) {
  EXPECT_EQ(oneLine("a\nb\rc\td\x01"
                    "e\x7F"
                    "f\xFF"),
            "a\\nb\\rc\\td\\x01e\\x7Ff" + kFffd);
  EXPECT_EQ(oneLine("caf\xC3\xA9 \\n"), "caf\xC3\xA9 \\n");  // UTF-8 and backslashes stay
}

TEST(SafeText, JsonStringsReadBackAsTheTextWithReplacements) {
  const char raw[] = "q\"b\\s/\b\f\n\r\t\x01\x1F\x7F \xC3\xA9 \xFF end\0x";
  const std::string text(raw, sizeof raw - 1);  // the NUL included
  std::string out;
  appendJsonString(out, text);
  std::string expected = text;
  expected.replace(expected.find('\xFF'), 1, kFffd);
  EXPECT_EQ(nlohmann::json::parse(out).get<std::string>(), expected) << out;
  // The same bytes nlohmann writes for valid text.
  std::string plain;
  appendJsonString(plain, expected);
  EXPECT_EQ(plain, nlohmann::json(expected).dump());
}

}  // namespace
}  // namespace relpos::cli
