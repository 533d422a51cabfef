// One reading of UTF-8 (io/src/utf8.cpp, relpos/io/text.hpp): whatever bytes come in, what goes
// out is UTF-8, each ill-formed subpart replaced once (Unicode's "maximal subparts") or, on one
// line, escaped byte by byte.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "relpos/io/text.hpp"

namespace relpos {
namespace {

const std::string kFffd = "\xEF\xBF\xBD";

TEST(Utf8, ValidUtf8IsKeptAndEachIllFormedSubpartReplacedOnce) {
  const std::string valid = "plain, \xC3\xA9, \xE2\x82\xAC, \xF0\x9F\x98\x80, \xF4\x8F\xBF\xBF";
  EXPECT_TRUE(isValidUtf8(valid));
  EXPECT_EQ(validUtf8(valid), valid);
  // Table 3-7's edges and how many U+FFFD each gives (Unicode 15 §3.9, table 3-8): overlong
  // forms, surrogates and beyond U+10FFFF one per byte; a sequence cut short, one in all.
  const std::pair<std::string, int> cases[] = {
      {"\xC0\xAF", 2},         {"\xE0\x80\xAF", 3}, {"\xED\xA0\x80", 3},
      {"\xF4\x90\x80\x80", 4}, {"\x80", 1},         {"\xFF", 1},
      {"\xE2\x82", 1},         {"\xF0\x9F\x98", 1}, {"\xF0\x9F\x98x", 1}};
  for (const auto& [bad, replacements] : cases) {
    EXPECT_FALSE(isValidUtf8(bad)) << bad;
    const std::string fixed = validUtf8("a" + bad + "b");
    EXPECT_TRUE(isValidUtf8(fixed));
    std::string expected;
    for (int i = 0; i < replacements; ++i) expected += kFffd;
    if (bad.back() == 'x') expected += 'x';
    EXPECT_EQ(fixed, "a" + expected + "b") << bad;
  }
  for (std::size_t at = 0; at < 20; ++at) {
    std::string s(20, 'x');
    s[at] = '\xFF';
    EXPECT_FALSE(isValidUtf8(s)) << at;
    EXPECT_EQ(validUtf8(s), std::string(at, 'x') + kFffd + std::string(19 - at, 'x'));
  }
}

TEST(Utf8, OneLineEscapesControlCharactersAndIllFormedBytes) {
  EXPECT_EQ(oneLine("a\nb\rc\td\x01"
                    "e\x7F"
                    "f\xFF"),
            "a\\nb\\rc\\td\\x01e\\x7Ff\\xFF");
  EXPECT_EQ(oneLine("caf\xC3\xA9 \\n"), "caf\xC3\xA9 \\n");            // UTF-8 and backslashes stay
  EXPECT_EQ(oneLine("caf\xC3"), "caf\\xC3");                           // cut short: its bytes shown
  EXPECT_EQ(oneLine("x\xC2\x85y\xE2\x80\xA8z"), "x\\u0085y\\u2028z");  // NEL, LINE SEPARATOR
  // Escaping twice changes nothing.
  const std::string once = oneLine("a\n\xFF\x01\xC2\x85");
  EXPECT_EQ(oneLine(once), once);
  EXPECT_TRUE(isValidUtf8(once));
}

}  // namespace
}  // namespace relpos
