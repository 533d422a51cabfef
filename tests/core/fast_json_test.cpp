// parseSpec reads plain specs with its own JSON reader (core/src/fast_json.hpp) and everything
// else through nlohmann. Both must give the same result, errors and warnings included: checked on
// every bundled spec and on thousands of mutations of them (a character deleted, inserted or
// replaced; a value swapped for an escape, a non-ASCII name, a duplicate key, an odd number).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "relpos/core/spec_io.hpp"
#include "relpos/rules/builtin.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string vec(const Vector3d& v) { return num(v.x()) + "," + num(v.y()) + "," + num(v.z()); }

std::string feature(const Feature& f) {
  return std::string(toString(f.kind)) + "(" + vec(f.point) + ";" + vec(f.direction) + ";" +
         num(f.radius) + ")";
}

std::string object(const ObjectSpec& o) {
  std::string s = o.name + " mesh=" + o.mesh + " pose=";
  for (int i = 0; i < 3; ++i) s += vec(o.pose.matrix().block<3, 1>(0, i)) + ";";
  s += vec(o.pose.translation()) + " features:";
  for (const auto& f : o.features) s += " " + f.name + "=" + feature(f.feature);
  return s;
}

// Everything parsing produced, as text.
std::string summary(const ParseResult& r) {
  std::ostringstream os;
  for (const auto& e : r.errors) os << "error " << e.path << ": " << e.message << "\n";
  for (const auto& w : r.warnings) os << "warning " << w.path << ": " << w.message << "\n";
  if (!r.problem) return os.str();
  const Problem& p = *r.problem;
  os << "name " << p.name << "\nfixed " << object(p.fixed) << "\nmobile " << object(p.mobile)
     << "\n";
  for (const auto& o : p.obstacles) os << "obstacle " << object(o) << "\n";
  for (const auto& c : p.constraints)
    os << "constraint " << c.type << " id=" << c.id << " " << c.fixed_name << "="
       << feature(c.fixed) << " " << c.mobile_name << "=" << feature(c.mobile)
       << " has_value=" << c.has_value << " value=" << num(c.value) << " min=" << num(c.min)
       << " max=" << num(c.max) << " orientation=" << toString(c.orientation)
       << " parallel=" << c.parallel << "\n";
  return os.str();
}

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

void expectSame(const std::string& text, const std::string& what) {
  const std::string fast = summary(parseSpec(text, builtinRegistry(), "spec"));
  const std::string library =
      summary(detail::parseSpecWithNlohmann(text, builtinRegistry(), "spec"));
  EXPECT_EQ(fast, library) << what << "\n" << text.substr(0, 400);
}

TEST(SpecReader, BundledSpecsParseAsWithTheJsonLibrary) {
  const auto texts = bundledTexts();
  ASSERT_GT(texts.size(), 150u);
  for (std::size_t i = 0; i < texts.size(); ++i)
    expectSame(texts[i], "bundled #" + std::to_string(i));
}

TEST(SpecReader, MutatedSpecsParseAsWithTheJsonLibrary) {
  const auto texts = bundledTexts();
  std::mt19937_64 rng(81);
  // Pieces that stress the reader: structure, escapes, non-ASCII, numbers at the grammar's edges.
  const std::vector<std::string> pieces = {"{",      "}",       "[",
                                           "]",      ",",       ":",
                                           "\"",     " ",       "\\",
                                           "\\n",    "\\u0041", "\xc3\xa9",
                                           "-0",     "-0.0",    "1e400",
                                           "1e-400", "01",      "1.",
                                           ".5",     "+1",      "1e",
                                           "1E+2",   "-",       "true",
                                           "false",  "null",    "\"name\":\"dup\",",
                                           "\t",     "\x01",    "123456789012345678901234567890",
                                           "\xc3",   "\xff"};
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    std::string t = texts[rng() % texts.size()];
    const std::size_t at = rng() % (t.size() + 1);
    switch (rng() % 3) {
      case 0:
        if (at < t.size()) t.erase(at, 1 + rng() % 3);
        break;
      case 1:
        t.insert(at, pieces[rng() % pieces.size()]);
        break;
      default:
        if (at < t.size()) t.replace(at, 1 + rng() % 4, pieces[rng() % pieces.size()]);
    }
    expectSame(t, "mutation #" + std::to_string(k));
    ++checked;
  }
  EXPECT_EQ(checked, 4000);
}

// The reader converts short numbers itself (Clinger's fast path) and the rest with from_chars:
// every form must give the double nlohmann gives, bit for bit (summary() prints 17 digits).
TEST(SpecReader, NumbersReadAsTheJsonLibraryReadsThem) {
  std::mt19937_64 rng(2026);
  std::vector<std::string> numbers = {"0",
                                      "-0",
                                      "0.0",
                                      "-0.0",
                                      "0e5",
                                      "-0e-5",
                                      "1",
                                      "-1",
                                      "0.1",
                                      "0.30000000000000004",
                                      "9007199254740992",
                                      "9007199254740993",
                                      "9007199254740991.5",
                                      "1e22",
                                      "1e23",
                                      "1e-22",
                                      "1e-23",
                                      "123456789e-22",
                                      "4.9e-324",
                                      "2.2e-308",
                                      "1.7976931348623157e308",
                                      "0.000001",
                                      "1E+2",
                                      "12.5e-1",
                                      "1234567890123456789",
                                      "12345678901234567890",
                                      "0.1234567890123456789012",
                                      "999999999999.99999999",
                                      "0.00000000000000000000001234567891234567"};
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
  // Digit strings of every length around the reader's eight-at-a-time steps and its 19-digit
  // mantissa, zeros included.
  std::uniform_int_distribution<int> length(0, 24), digit(0, 9);
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
  for (const std::string& n : numbers)
    expectSame(R"({"fixed": {"pose": {"position": [)" + n + R"(, 0, 0]}, "features": {"p":
               {"point": [0, 0, 0]}}}, "mobile": {"features": {"q": {"point": [0, 0, 0]}}},
               "constraints": [{"type": "distance", "fixed": "p", "mobile": "q", "value": )" +
                   n + "}]}",
               n);
}

TEST(SpecReader, DuplicateKeysAndEscapesGoToTheJsonLibrary) {
  // Both paths must agree here too: these are the cases the fast reader hands over.
  expectSame(R"({"name": "a", "name": "b", "fixed": {}, "mobile": {}, "constraints": []})", "dup");
  expectSame(R"({"name": "caf\u00e9 \"q\"", "fixed": {}, "mobile": {}, "constraints": []})", "esc");
  expectSame("{\"name\": \"caf\xc3\xa9\", \"fixed\": {}, \"mobile\": {}, \"constraints\": []}",
             "utf8");
  expectSame(R"({"relpos": -0, "fixed": {}, "mobile": {}, "constraints": []})", "-0");
}

}  // namespace
}  // namespace relpos::test
