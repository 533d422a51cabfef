// The spec reader (simdjson with relpos's diagnostics, io/src/json_read.hpp) on every kind of
// text: numbers read exactly as strtod reads them, malformed text named by line and column (also
// when it holds non-ASCII or invalid UTF-8), any depth of nesting refused without a crash, keys
// and feature names twice refused at their JSON path in linear time, numbers beyond a double
// refused at their path and position, every diagnostic on one line; and thousands of mutated
// bundled specs read or refused the way an independent JSON library (nlohmann) sees them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_helpers.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

std::string all(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += d.path + ": " + d.message + "\n";
  return s;
}

// A spec whose fixed object sits at [n, 0, 0] (n: a number token).
std::string specWithPosition(const std::string& n) {
  return R"({"fixed": {"pose": {"position": [)" + n +
         R"(, 0, 0]}, "features": {}}, "mobile": {"features": {}}, "constraints": []})";
}

// --- numbers --------------------------------------------------------------------------------

// Every spelling of a number gives the double strtod gives (simdjson converts most; integers
// beyond 64 bits go through json_read.cpp's widening): bit for bit. The one exception is
// documented: an integer zero written "-0" is the integer 0, so +0.0 ("-0.0" keeps its sign).
TEST(SpecReader, NumbersReadAsStrtodReadsThem) {
  std::mt19937_64 rng(2026);
  std::vector<std::string> numbers = {
      "0", "-0", "0.0", "-0.0", "0e5", "-0e-5", "1", "-1", "0.1", "0.30000000000000004",
      "9007199254740992", "9007199254740993", "9007199254740991.5", "1e22", "1e23", "1e-22",
      "1e-23", "123456789e-22", "4.9e-324", "2.2e-308", "1.7976931348623157e308", "0.000001",
      "1E+2", "12.5e-1", "1234567890123456789", "12345678901234567890", "0.1234567890123456789012",
      "999999999999.99999999", "0.00000000000000000000001234567891234567",
      // Tiny numbers are valid doubles: zero or subnormal.
      "1e-400", "-1e-400", "2.4703282292062328e-324", "2.4703282292062327e-324", "2e-320",
      // Integers around and beyond 64 bits.
      "9223372036854775807", "9223372036854775808", "-9223372036854775808", "-9223372036854775809",
      "18446744073709551615", "18446744073709551616", "99999999999999999999",
      "-99999999999999999999", "10000000000000000000000000", "123456789012345678901234567890"};
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30), digits(1, 19);
  std::bernoulli_distribution nine(0.3);  // many nines: the largest mantissas
  char buf[64];
  for (int k = 0; k < 3000; ++k) {
    const double v = unit(rng) * std::pow(10.0, exponent(rng));
    const char* forms[] = {"%.*g", "%.*e", "%.*f"};
    std::snprintf(buf, sizeof buf, forms[k % 3], k % 3 == 2 ? digits(rng) % 12 : digits(rng), v);
    numbers.push_back(buf);
  }
  std::uniform_int_distribution<int> length(0, 24), digit(0, 9), wide(19, 300);
  auto digitString = [&](int len, bool leading_zero_ok) {
    std::string d;
    for (int i = 0; i < len; ++i) {
      int x = digit(rng);
      if (i == 0 && !leading_zero_ok && x == 0) x = 9;
      d += static_cast<char>('0' + (nine(rng) ? 9 : x));
    }
    return d;
  };
  for (int k = 0; k < 3000; ++k) {
    const int int_len = 1 + length(rng);
    std::string n = (k % 2 ? "-" : "") +
                    (int_len == 1 && k % 3 == 0 ? std::string("0") : digitString(int_len, false));
    if (k % 4 != 0) n += "." + digitString(1 + length(rng), true);
    if (k % 5 == 0) n += "e" + std::to_string(exponent(rng));
    numbers.push_back(n);
  }
  // Integers too wide for 64 bits (up to 300 digits: within a double's range).
  for (int k = 0; k < 500; ++k)
    numbers.push_back((k % 2 ? "-" : "") + digitString(wide(rng), false));
  for (const std::string& n : numbers) {
    const ParseResult r = parse(specWithPosition(n));
    ASSERT_TRUE(r.problem) << n << ": " << all(r.errors);
    const bool integral = n.find_first_of(".eE") == std::string::npos;
    double expected = std::strtod(n.c_str(), nullptr);
    if (integral && expected == 0.0) expected = 0.0;  // "-0": the integer 0
    EXPECT_TRUE(sameDouble(r.problem->fixed.pose.translation().x(), expected))
        << n << " read as " << r.problem->fixed.pose.translation().x();
  }
}

TEST(SpecReader, NumbersBeyondADoubleAreErrorsWithPathAndPosition) {
  // Columns counted by hand: line 3 is `  "P": {"point": [1e400, 0, 0]}}},`, the number at 19.
  const std::string text =
      "{\"relpos\": 1,\n"
      " \"fixed\": {\"features\": {\n"
      "  \"P\": {\"point\": [1e400, 0, 0]}}},\n"
      " \"mobile\": {\"features\": {\"q\": {\"point\": [0, 0, -1e400]}}},\n"
      " \"constraints\": [], \"extra\": [0, 1E+999]}";
  const ParseResult r = parse(text);
  EXPECT_FALSE(r.problem);
  ASSERT_EQ(r.errors.size(), 3u) << all(r.errors);
  EXPECT_EQ(r.errors[0].path, "fixed.features.P.point[0]");
  EXPECT_EQ(r.errors[0].message, "number out of the range of a double '1e400' (line 3, column 19)");
  EXPECT_EQ(r.errors[1].path, "mobile.features.q.point[2]");
  EXPECT_EQ(r.errors[1].message,
            "number out of the range of a double '-1e400' (line 4, column 48)");
  EXPECT_EQ(r.errors[2].path, "extra[1]");
  EXPECT_EQ(r.errors[2].message,
            "number out of the range of a double '1E+999' (line 5, column 34)");
  // An integer of 400 digits; a path through escaped keys (shown decoded, then escaped).
  const ParseResult wide = parse(R"({"a\u0041": {"b\nc": [)" + std::string(400, '7') + "]}}");
  ASSERT_EQ(wide.errors.size(), 1u) << all(wide.errors);
  EXPECT_EQ(wide.errors[0].path, "aA.b\\nc[0]");
  EXPECT_EQ(wide.errors[0].message, "number out of the range of a double '" + std::string(40, '7') +
                                        "...' (line 1, column 23)");
}

// --- malformed text -------------------------------------------------------------------------

TEST(SpecReader, MalformedJsonNamesLineColumnAndWhat) {
  // Columns count characters (é is one) from 1; expected messages written by hand.
  const std::pair<std::string, std::string> cases[] = {
      {"{\n  \"relpos\": 1,\n  \"fixed\": {,\n}",
       "line 3, column 13: expected a key (a string) or '}', got ','"},
      {"", "line 1, column 1: expected a value, got the end of the text"},
      {"  \n", "line 2, column 1: expected a value, got the end of the text"},
      {"{} x", "line 1, column 4: expected the end of the text after the document, got 'x'"},
      {std::string("[1]\0", 4),
       "line 1, column 4: expected the end of the text after the document, got '\\0'"},
      {"[1 2]", "line 1, column 4: expected ',' or ']', got '2'"},
      {"{\"a\": 1 \"b\": 2}", "line 1, column 9: expected ',' or '}', got '\"'"},
      {"[01]", "line 1, column 2: invalid number '01'"},
      {"[1.]", "line 1, column 2: invalid number '1.'"},
      {"[-]", "line 1, column 2: invalid number '-'"},
      {"[1e]", "line 1, column 2: invalid number '1e'"},
      {"[\"a\nb\"]",
       "line 1, column 4: control character '\\n' in a string (write it as an escape)"},
      {"[\"\\q\"]", "line 1, column 3: invalid escape '\\q' in a string"},
      {"[\"\\uD800\"]", "line 1, column 3: unpaired UTF-16 surrogate '\\uD800' in a string"},
      {"[\"\\uDC00\\uD800\"]", "line 1, column 3: unpaired UTF-16 surrogate '\\uDC00' in a string"},
      {"[\"\\uD800\\u0041\"]", "line 1, column 3: unpaired UTF-16 surrogate '\\uD800' in a string"},
      {"[\"\\u12G4\"]",
       "line 1, column 3: invalid escape '\\u12G4' in a string (\\u takes four hexadecimal "
       "digits)"},
      {"[tru]", "line 1, column 2: expected a value, got 'tru'"},
      {"nul", "line 1, column 1: expected a value, got 'nul'"},
      {"[\"abc", "line 1, column 2: unterminated string (no closing '\"')"},
      {"[\"\xc3\xa9\", x]", "line 1, column 7: expected a value, got 'x'"},
      {"{\"a\" 1}", "line 1, column 6: expected ':' after the key, got '1'"},
      {"{\"a\":1,}", "line 1, column 8: expected a key (a string), got '}'"},
      {"[1,]", "line 1, column 4: expected a value, got ']'"},
      {"{\t\"a\":\tx}", "line 1, column 8: expected a value, got 'x'"},
      {"\n\n   [1,\n  }", "line 4, column 3: expected a value, got '}'"},
      // The issue's line: a non-ASCII character where a value belongs.
      {"{\"relpos\": 1, \"name\": \xc3\xa9}",
       "line 1, column 23: expected a value, got '\xc3\xa9'"},
      // Bytes that are not UTF-8, in a string and outside: shown escaped.
      {"{\"name\": \"a\xff b\"}", "line 1, column 12: invalid UTF-8 '\\xFF' in a string"},
      {"{\"name\": \"caf\xc3\"}", "line 1, column 14: invalid UTF-8 '\\xC3' in a string"},
      {"{\"name\": \"\xed\xa0\x80\"}", "line 1, column 11: invalid UTF-8 '\\xED' in a string"},
      {"{\"a\": \xff}", "line 1, column 7: expected a value, got '\\xFF'"},
      {"{\"a\": \xe2\x80\xa8}", "line 1, column 7: expected a value, got '\\u2028'"},
  };
  for (const auto& [text, expected] : cases) {
    const ParseResult r = parse(text);
    EXPECT_FALSE(r.problem);
    ASSERT_EQ(r.errors.size(), 1u) << text << "\n" << all(r.errors);
    EXPECT_EQ(r.errors[0].path, "");
    EXPECT_EQ(r.errors[0].message, "malformed JSON at " + expected) << text;
    EXPECT_EQ(r.name, "t");
    EXPECT_NO_THROW((void)nlohmann::json(r.errors[0].message).dump()) << "not UTF-8";
  }
}

// Nesting is bounded (1024 arrays and objects) and refused with a message naming the limit, at
// any depth: 3×10^5 brackets once crashed the reader.
TEST(SpecReader, DeepNestingIsRefusedNamingTheLimit) {
  const std::string limit = "more than 1024 arrays and objects inside each other";
  auto expectTooDeep = [&](const std::string& text, const std::string& where) {
    const ParseResult r = parse(text);
    EXPECT_FALSE(r.problem);
    ASSERT_EQ(r.errors.size(), 1u) << all(r.errors);
    EXPECT_EQ(r.errors[0].path, "");
    EXPECT_EQ(r.errors[0].message, "too deeply nested at " + where + ": " + limit);
  };
  // The 1025th bracket is at column 1025; the 1025th "{" of {"a":{"a":... at 5 × 1024 + 1.
  expectTooDeep(std::string(300000, '['), "line 1, column 1025");
  std::string objects;
  for (int i = 0; i < 300000; ++i) objects += "{\"a\":";
  expectTooDeep(objects, "line 1, column 5121");
  // Deeper than relpos's limit but within simdjson's (its own limit is a little higher).
  expectTooDeep(std::string(1025, '[') + std::string(1025, ']'), "line 1, column 1025");
  // In an unknown field of an otherwise valid spec: the document and 1024 arrays of "extra"
  // hold the innermost, whose "[" is at column 10 + 1024.
  auto withExtra = [](int n) {
    return "{\"extra\": " + std::string(static_cast<std::size_t>(n), '[') +
           std::string(static_cast<std::size_t>(n), ']') +
           R"(, "fixed": {"features": {}}, "mobile": {"features": {}}, "constraints": []})";
  };
  expectTooDeep(withExtra(1024), "line 1, column 1034");
  // At the limit: read.
  const ParseResult ok = parse(withExtra(1023));
  EXPECT_TRUE(ok.problem) << all(ok.errors);
  const ParseResult arrays = parse(std::string(1024, '[') + std::string(1024, ']'));
  ASSERT_EQ(arrays.errors.size(), 1u);
  EXPECT_EQ(arrays.errors[0].message, "the spec must be a JSON object");
}

// --- keys twice -----------------------------------------------------------------------------

const char* kValid = R"({"relpos": 1,
  "fixed": {"pose": {"position": [0, 0, 0]}, "features": {
    "P": {"point": [0, 0, 0]}, "K": {"line": {"point": [0, 0, 0], "direction": [0, 0, 1]}}}},
  "mobile": {"features": {"q": {"point": [0, 0, 0]}}},
  "constraints": [{"type": "coincident", "fixed": "P", "mobile": "q"}],
  "extra": {"a": [1, {"b": 1}]}})";

// kValid with `from` (once) replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

std::vector<std::string> duplicatePaths(const ParseResult& r) {
  std::vector<std::string> paths;
  for (const auto& e : r.errors)
    if (e.message == "duplicate key (each key may appear once in an object)")
      paths.push_back(e.path);
  return paths;
}

TEST(SpecReader, KeysTwiceInAnObjectAreErrorsAtTheirPath) {
  ASSERT_TRUE(parse(kValid).problem) << all(parse(kValid).errors);
  using Paths = std::vector<std::string>;
  const std::pair<std::string, Paths> cases[] = {
      {edited("\"relpos\": 1,", "\"relpos\": 1, \"relpos\": 1,"), {"relpos"}},
      {edited("\"relpos\": 1,", "\"relpos\": 1, \"relpos\": 1, \"relpos\": 1,"),
       {"relpos", "relpos"}},
      {edited("[0, 0, 0]}, \"features\"", "[0, 0, 0], \"position\": [1, 1, 1]}, \"features\""),
       {"fixed.pose.position"}},
      // A feature name twice (the last used to win silently).
      {edited("\"K\": {\"line\"", "\"P\": {\"point\": [1, 1, 1]}, \"K\": {\"line\""),
       {"fixed.features.P"}},
      {edited("\"direction\": [0, 0, 1]", "\"direction\": [0, 0, 1], \"point\": [1, 0, 0]"),
       {"fixed.features.K.line.point"}},
      {edited("\"type\": \"coincident\",", "\"type\": \"coincident\", \"type\": \"parallel\","),
       {"constraints[0].type"}},
      // Unknown fields twice, and keys twice inside an unknown field's value.
      {edited("\"mobile\": \"q\"}", "\"mobile\": \"q\", \"colour\": 1, \"colour\": 2}"),
       {"constraints[0].colour"}},
      {edited("{\"b\": 1}", "{\"b\": 1, \"b\": 2}"), {"extra.a[1].b"}},
      {edited("\"extra\"", "\"x\": 1, \"x\": 2, \"extra\""), {"x"}},
      // With other errors in the spec, every duplicate is still found.
      {edited("\"type\": \"coincident\",", "\"type\": \"welded\", \"id\": \"a\", \"id\": \"b\","),
       {"constraints[0].id"}},
      {edited("\"P\": {\"point\": [0, 0, 0]}", "\"P\": {\"point\": [0, 0, 0], \"point\": [1, 1]}"),
       {"fixed.features.P.point"}},
      {edited("{\"b\": 1}", "{\"b\": {\"c\": [{\"d\": 0, \"d\": 0}]}, \"b\": 2}") + "x",
       {}},  // malformed: nothing else is read
  };
  for (const auto& [text, expected] : cases) {
    const ParseResult r = parse(text);
    EXPECT_FALSE(r.problem) << text;
    EXPECT_EQ(duplicatePaths(r), expected) << text << "\n" << all(r.errors);
  }
}

// A member named "" has a path of its own: joined by '.' it would vanish, and at the top level
// its warning would name the empty path, the document's.
TEST(SpecReader, AnEmptyKeyIsNamedInThePath) {
  const ParseResult top = parse(edited("\"relpos\": 1,", "\"relpos\": 1, \"\": 0,"));
  ASSERT_TRUE(top.problem) << all(top.errors);
  ASSERT_FALSE(top.warnings.empty());
  EXPECT_EQ(top.warnings[0].path, "[\"\"]");
  EXPECT_EQ(top.warnings[0].message, "unknown field (ignored)");
  const ParseResult twice = parse(edited("{\"b\": 1}", "{\"\": {\"\": 1, \"\": 2}}"));
  EXPECT_EQ(duplicatePaths(twice), std::vector<std::string>{"extra.a[1][\"\"][\"\"]"});
}

// A feature named "C.axis" beside a cylinder "C" would make the name "C.axis" mean two things.
TEST(SpecReader, AFeatureNamedLikeACylinderAxisIsAmbiguous) {
  const std::string cylinder = R"("C": {"cylinder": {"point": [0, 0, 0], "direction": [0, 0, 1],
                                  "radius": 1}}, "K": {"line")";
  const ParseResult r =
      parse(edited("\"K\": {\"line\"", R"("C.axis": {"point": [0, 0, 0]}, )" + cylinder));
  ASSERT_EQ(r.errors.size(), 1u) << all(r.errors);
  EXPECT_EQ(r.errors[0].path, "fixed.features.C.axis");
  EXPECT_EQ(r.errors[0].message, "ambiguous name: 'C.axis' is also the axis of the cylinder 'C'");
  // Beside a point "C" there is no axis to confuse it with.
  EXPECT_TRUE(parse(edited("\"K\": {\"line\"", R"("C.axis": {"point": [0, 0, 0]},
                               "C": {"point": [1, 0, 0]}, "K": {"line")"))
                  .problem);
}

// A 3 MB object of 200,000 keys, and 40,000 features with as many constraints, are read in
// linear time (ctest's timeout catches a quadratic regression: it took minutes).
TEST(SpecReader, LargeObjectsAreReadInLinearTime) {
  const std::string rest =
      R"("fixed": {"features": {}}, "mobile": {"features": {}}, "constraints": []})";
  std::string keys;
  for (int i = 0; i < 200000; ++i) keys += "\"key_" + std::to_string(i) + "\": 0.5, ";
  const ParseResult inside = parse("{\"extra\": {" + keys + "\"end\": 0}, " + rest);
  EXPECT_TRUE(inside.problem) << all(inside.errors);
  EXPECT_EQ(inside.warnings.size(), 2u);  // "extra", and no constraints
  const ParseResult twice = parse("{\"extra\": {" + keys + "\"key_7\": 0}, " + rest);
  EXPECT_EQ(duplicatePaths(twice), std::vector<std::string>{"extra.key_7"});
  // The same keys as unknown fields of the spec itself.
  const ParseResult top = parse("{" + keys + rest);
  EXPECT_TRUE(top.problem) << all(top.errors);
  EXPECT_EQ(top.warnings.size(), 200001u);
  const ParseResult top_twice = parse("{" + keys + "\"key_199999\": 1, " + rest);
  EXPECT_EQ(duplicatePaths(top_twice), std::vector<std::string>{"key_199999"});

  std::string features, constraints;
  for (int i = 0; i < 40000; ++i) {
    features += "\"f" + std::to_string(i) + "\": {\"point\": [" + std::to_string(i) + ", 0, 0]}, ";
    constraints += std::string(i ? ", " : "") + R"({"type": "coincident", "fixed": "f)" +
                   std::to_string(i) + R"(", "mobile": "q"})";
  }
  const std::string spec = "{\"fixed\": {\"features\": {" + features +
                           "\"end\": {\"point\": [0, 0, 0]}}}, \"mobile\": {\"features\": {\"q\": "
                           "{\"point\": [0, 0, 0]}}}, \"constraints\": [" +
                           constraints + "]}";
  const ParseResult many = parse(spec);
  ASSERT_TRUE(many.problem) << all(many.errors).substr(0, 1000);
  EXPECT_EQ(many.problem->fixed.features.size(), 40001u);
  ASSERT_EQ(many.problem->constraints.size(), 40000u);
  EXPECT_EQ(many.problem->constraints[39999].fixed.point.x(), 39999.0);
  std::string dup = spec;
  dup.replace(dup.find("\"end\""), 5, "\"f123\"");
  const ParseResult many_twice = parse(dup);
  EXPECT_EQ(duplicatePaths(many_twice), std::vector<std::string>{"fixed.features.f123"});
}

// --- one line per diagnostic ----------------------------------------------------------------

TEST(SpecReader, EchoedTextIsEscapedOntoOneLine) {
  const ParseResult r =
      parse(edited(R"("constraints": [{"type": "coincident", "fixed": "P", "mobile": "q"}])",
                   R"("\u0001x": 1, "constraints": [
        {"type": "coincident", "fixed": "no\u0000pe", "mobile": "q", "id": "g\r1"},
        {"type": "we\u2028ld", "fixed": "P", "mobile": "q"},
        {"type": "coincident", "fixed": "P", "mobile": "q\nq"}])"));
  ASSERT_EQ(r.errors.size(), 3u) << all(r.errors);
  EXPECT_EQ(r.errors[0].path, "constraints[0].fixed");
  EXPECT_EQ(r.errors[0].message,
            "no feature 'no\\0pe' on fixed object 'fixed' (it has: P, K) (constraint id 'g\\r1')");
  EXPECT_EQ(r.errors[1].message,
            "unknown constraint type 'we\\u2028ld' (load the plugin that provides it)");
  EXPECT_EQ(r.errors[2].message, "no feature 'q\\nq' on mobile object 'mobile' (it has: q)");
  ASSERT_EQ(r.warnings.size(), 2u) << all(r.warnings);  // "\u0001x" and "extra"
  EXPECT_EQ(r.warnings[0].path, "\\x01x");
  const ParseResult kind = parse(edited("{\"line\"", "{\"li\\u007Fne\\tx\""));
  ASSERT_EQ(kind.errors.size(), 1u) << all(kind.errors);
  EXPECT_EQ(kind.errors[0].path, "fixed.features.K.li\\x7Fne\\tx");
  EXPECT_EQ(kind.errors[0].message,
            "unknown feature kind 'li\\x7Fne\\tx' (expected point, line, plane or cylinder)");
  // The file name too, with bytes that are not UTF-8; already escaped text stays as it is.
  const Diagnostic d{"a.b", "it\tis"};
  EXPECT_EQ(formatDiagnostic("sp\xff"
                             "ec\n.json",
                             d),
            "sp\\xFFec\\n.json: a.b: it\\tis");
  EXPECT_EQ(formatDiagnostic("caf\xc3\xa9.json", {"", "x"}), "caf\xc3\xa9.json: x");
  EXPECT_EQ(formatDiagnostic("a\\n.json", {"", "b\\x01"}), "a\\n.json: b\\x01");
}

// --- the spec's name ------------------------------------------------------------------------

TEST(SpecReader, TheNameIsKnownAlsoWhenTheSpecIsInvalid) {
  EXPECT_EQ(parse(R"({"name": "my-spec", "relpos": 2})").name, "my-spec");
  EXPECT_EQ(parse(R"({"name": "my-spec", "relpos": )").name, "t");  // malformed: the default
  EXPECT_EQ(parse(R"({"name": 5})").name, "t");
  EXPECT_EQ(parse(kValid).name, "t");
  // A default name that is not UTF-8 (from a file name): U+FFFD in its place.
  const ParseResult bad = parseSpec(kValid, builtinRegistry(), "bad\xff");
  ASSERT_TRUE(bad.problem);
  EXPECT_EQ(bad.name, "bad\xef\xbf\xbd");
  EXPECT_EQ(bad.problem->name, "bad\xef\xbf\xbd");
  const std::string file = ::testing::TempDir() + "name\xfflless.json";
  std::ofstream(file) << kValid;
  const ParseResult from_file = parseSpecFile(file, builtinRegistry());
  ASSERT_TRUE(from_file.problem);
  EXPECT_EQ(from_file.problem->name, "name\xef\xbf\xbdlless");
}

TEST(SpecReader, ADirectoryIsNotASpec) {
  const ParseResult r = parseSpecFile(::testing::TempDir(), builtinRegistry());
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].message, "is a directory, not a spec file");
  EXPECT_TRUE(specPluginPaths(::testing::TempDir()).empty());
}

TEST(SpecReader, PluginListsAreReadWithTheSameReader) {
  const std::string with_wide =
      R"({"plugins": ["a.so", "/b.so"], "extra": 123456789012345678901234567890})";
  EXPECT_EQ(specPluginPathsInText(with_wide, "dir"),
            (std::vector<std::string>{"dir/a.so", "/b.so"}));
  EXPECT_TRUE(specPluginPathsInText(R"({"plugins": ["a.so"], )", "dir").empty());
  EXPECT_TRUE(specPluginPathsInText(std::string(300000, '[') + "\"plugins\"", "").empty());
}

// --- mutations ------------------------------------------------------------------------------

std::vector<std::string> bundledTexts() {
  std::vector<std::string> texts;
  for (const char* dir : {"examples", "scenarios", "rules", "collision", "plugins"})
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + dir))
      if (e.path().extension() == ".json") {
        std::ifstream in(e.path());
        std::stringstream ss;
        ss << in.rdbuf();
        texts.push_back(ss.str());
      }
  std::ifstream in(RELPOS_DATA_DIR "/batch/grasp-and-weld-100.jsonl");
  for (std::string line; std::getline(in, line);) texts.push_back(line);
  return texts;
}

// Keys seen twice in one object, by nlohmann's SAX parser (the independent count).
struct DuplicateCounter : nlohmann::json_sax<nlohmann::json> {
  std::vector<std::set<std::string>> open;
  int duplicates = 0;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    open.emplace_back();
    return true;
  }
  bool key(string_t& k) override {
    duplicates += open.back().insert(k).second ? 0 : 1;
    return true;
  }
  bool end_object() override {
    open.pop_back();
    return true;
  }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;
  }
};

bool oneLineUtf8(const std::string& s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  try {
    (void)nlohmann::json(s).dump();  // throws on bytes that are not UTF-8
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

// Every mutation of a bundled spec is read or refused as nlohmann sees it (its own grammar,
// UTF-8 and range checks), every duplicate key it counts is reported, every diagnostic is one
// line of UTF-8, and none is the reader's "cannot happen" fallback.
TEST(SpecReader, MutatedSpecsAreReadOrRefusedAsAnotherJsonLibrarySeesThem) {
  const auto texts = bundledTexts();
  ASSERT_GT(texts.size(), 150u);
  std::mt19937_64 rng(81);
  // Pieces that stress the reader: structure, escapes, non-ASCII, numbers at the grammar's edges,
  // keys that may land twice in an object.
  const std::vector<std::string> pieces = {"{",
                                           "}",
                                           "[",
                                           "]",
                                           ",",
                                           ":",
                                           "\"",
                                           " ",
                                           "\\",
                                           "\\n",
                                           "\\u0041",
                                           "\\ud800",
                                           "\xc3\xa9",
                                           "-0",
                                           "-0.0",
                                           "1e400",
                                           "-1e999",
                                           "1e-400",
                                           "01",
                                           "1.",
                                           ".5",
                                           "+1",
                                           "1e",
                                           "1E+2",
                                           "-",
                                           "true",
                                           "false",
                                           "null",
                                           "\"name\":\"dup\",",
                                           "\"type\":\"distance\",",
                                           "\"point\":[0,0,0],",
                                           "\"x\":1,\"x\":2,",
                                           "\t",
                                           "\x01",
                                           "123456789012345678901234567890",
                                           "\xc3",
                                           "\xff",
                                           "\xed\xa0\x80",
                                           "\xe2\x80\xa8"};
  // Members put first into an object (after a '{'): often a key the object already has.
  const std::vector<std::string> members = {
      "\"type\":\"distance\",", "\"point\":[0,0,0],", "\"name\":\"dup\",", "\"features\":{},",
      "\"value\":1,",           "\"relpos\":1,",      "\"fixed\":\"a\",",  "\"position\":[1,2,3],"};
  int refused = 0, duplicates = 0;
  for (int k = 0; k < 4000; ++k) {
    std::string t = texts[rng() % texts.size()];
    const std::size_t at = rng() % (t.size() + 1);
    switch (rng() % 4) {
      case 3: {
        const std::size_t brace = t.find('{', at);
        if (brace != std::string::npos) t.insert(brace + 1, members[rng() % members.size()]);
        break;
      }
      case 0:
        if (at < t.size()) t.erase(at, 1 + rng() % 3);
        break;
      case 1:
        t.insert(at, pieces[rng() % pieces.size()]);
        break;
      default:
        if (at < t.size()) t.replace(at, 1 + rng() % 4, pieces[rng() % pieces.size()]);
    }
    const ParseResult r = parse(t);
    bool malformed = false, out_of_range = false;
    int reported_duplicates = 0;
    for (const auto* list : {&r.errors, &r.warnings})
      for (const auto& d : *list) {
        EXPECT_TRUE(oneLineUtf8(d.path) && oneLineUtf8(d.message)) << d.path << ": " << d.message;
        EXPECT_EQ(d.message.find("cannot read the JSON"), std::string::npos) << d.message;
        malformed = malformed || d.message.rfind("malformed JSON at line ", 0) == 0;
        out_of_range =
            out_of_range || d.message.rfind("number out of the range of a double", 0) == 0;
        reported_duplicates += d.message.rfind("duplicate key", 0) == 0 ? 1 : 0;
      }
    const bool accepted = nlohmann::json::accept(t);
    EXPECT_EQ(accepted, !malformed && !out_of_range) << "mutation #" << k << "\n"
                                                     << all(r.errors) << t.substr(0, 400);
    refused += accepted ? 0 : 1;
    if (accepted) {
      DuplicateCounter counter;
      nlohmann::json::sax_parse(t, &counter);
      EXPECT_EQ(reported_duplicates, counter.duplicates) << "mutation #" << k << "\n"
                                                         << all(r.errors) << t.substr(0, 400);
      duplicates += counter.duplicates;
    }
    if (r.problem) {
      EXPECT_TRUE(r.errors.empty());
    }
  }
  // The mutations reach both sides.
  EXPECT_GT(refused, 500);
  EXPECT_GT(duplicates, 100);
}

}  // namespace
}  // namespace relpos::test
