// The result line (writeResultLine) is the JSON document docs/spec.md §2 describes: valid JSON in
// valid UTF-8 whatever the names hold, the same document as the indented one `relpos solve` prints
// (both written from one Report), and every number in it
// reads back as exactly the double it was written from, in the fewest digits that do so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "io_test_helpers.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/result_writer.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"
#include "test_config.hpp"
#include "test_fallback.hpp"

namespace relpos::test {
namespace {

using json = nlohmann::ordered_json;

std::vector<Problem> readBundledProblems() {
  std::vector<Problem> v;
  for (const char* dir : {"examples", "scenarios", "rules"})
    for (const auto& e :
         std::filesystem::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + dir))
      if (e.path().extension() == ".json") {
        ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
        if (r.problem) v.push_back(*r.problem);
      }
  std::ifstream in(RELPOS_DATA_DIR "/batch/grasp-and-weld-100.jsonl");
  for (std::string line; std::getline(in, line);) {
    ParseResult r = parseSpec(line, builtinRegistry());
    if (r.problem) v.push_back(*r.problem);
  }
  return v;
}

const std::vector<Problem>& bundledProblems() {
  static const std::vector<Problem> problems = readBundledProblems();
  return problems;
}

// The indented document of the same Report, read back.
json documentTree(const Problem& p, const Solution& s, const ReportOptions& opt) {
  std::string text;
  writeReport(evaluate(p, s, opt), kResultDocument, text);
  return json::parse(text);
}

// The value read back is the very double (== would not tell -0.0 from 0.0); null for a
// non-finite one. A float in the JSON sense, so every reader takes it as a double.
void expectNumber(const json& j, double v, const std::string& what) {
  if (!std::isfinite(v)) {
    EXPECT_TRUE(j.is_null()) << what << ": " << j.dump();
    return;
  }
  ASSERT_TRUE(j.is_number_float()) << what << ": " << j.dump();
  EXPECT_TRUE(sameDouble(j.get<double>(), v))
      << what << ": wrote " << v << ", read back " << j.get<double>();
}

// The orientation docs/spec.md writes: the unit quaternion with w >= 0 (computed here on its own).
Eigen::Vector4d orientation(const Isometry3d& X) {
  Quaterniond q(X.linear());
  q.normalize();
  return q.w() < 0 ? Eigen::Vector4d(-q.coeffs()) : Eigen::Vector4d(q.coeffs());
}

void expectPose(const json& j, const Isometry3d& X, const Params& theta, int dof,
                const std::string& what) {
  ASSERT_EQ(j["parameters"].size(), static_cast<std::size_t>(dof)) << what;
  for (int i = 0; i < dof; ++i)
    expectNumber(j["parameters"][static_cast<std::size_t>(i)], theta[i], what + " parameter");
  for (int i = 0; i < 3; ++i)
    expectNumber(j["position"][static_cast<std::size_t>(i)], X.translation()[i],
                 what + " position");
  const Eigen::Vector4d q = orientation(X);
  for (int i = 0; i < 4; ++i)
    expectNumber(j["orientation"][static_cast<std::size_t>(i)], q[i], what + " orientation");
}

// The first n keys of an object in the order written (all of them when n is 0), each followed by
// a space.
std::string keysOf(const json& j, std::size_t n = 0) {
  std::string keys;
  for (const auto& [k, v] : j.items()) {
    keys += k + " ";
    if (--n == 0) break;
  }
  return keys;
}

// Every number of the line against the double it comes from, recomputed here: the parameter
// bounds, the nearest pose and its distance, the samples (the same generator, drawn in the same
// order), the solve time.
void expectLine(const Problem& p, const ReportOptions& opt) {
  const Solution s = solve(p, builtinRegistry());
  std::string line;
  writeResultLine(p, s, opt, line);
  const json doc = json::parse(line);  // throws on malformed JSON or UTF-8
  EXPECT_EQ(doc, documentTree(p, s, opt)) << p.name;
  EXPECT_EQ(doc["name"], p.name);
  // "complete" right after "status", each branch's "exact" right after "manifold", and
  // "certified" exactly when it is not exact: as the Solution says.
  EXPECT_EQ(keysOf(doc, 6), "relpos name status complete isolated_complete message ") << p.name;
  EXPECT_EQ(doc["isolated_complete"], s.isolated_complete) << p.name;
  if (s.complete) {
    EXPECT_TRUE(s.isolated_complete) << p.name;
  }
  EXPECT_EQ(doc["complete"], s.complete) << p.name;
  for (std::size_t b = 0; b < s.branches.size(); ++b) {
    const json& jb = doc["branches"][b];
    EXPECT_EQ(jb["exact"], s.branches[b].exact) << p.name;
    EXPECT_EQ(jb.contains("certified"), !s.branches[b].exact) << p.name;
    EXPECT_EQ(keysOf(jb, 5), "dof rotational_dof translational_dof manifold exact ") << p.name;
  }
  // The rules' answers (no numeric stage registered): complete when solved or inconsistent.
  if (!builtinRegistry().fallback()) {
    EXPECT_EQ(doc["complete"].get<bool>(),
              s.status == Status::kSolved || s.status == Status::kInconsistent)
        << p.name;
    for (const json& jb : doc["branches"]) EXPECT_EQ(jb["exact"], true) << p.name;
  }
  expectNumber(doc["stats"]["solve_us"], s.solve_us, p.name + " solve_us");
  ASSERT_EQ(doc["branches"].size(), s.branches.size()) << p.name;
  std::mt19937_64 rng(opt.seed);
  for (std::size_t b = 0; b < s.branches.size(); ++b) {
    const json& jb = doc["branches"][b];
    const Manifold& m = *s.branches[b].manifold;
    const std::string what = p.name + " branch " + std::to_string(b);
    ASSERT_EQ(jb["parameters"].size(), static_cast<std::size_t>(m.dof())) << what;
    for (int i = 0; i < m.dof(); ++i) {
      const Parameter par = m.parameter(i);
      expectNumber(jb["parameters"][static_cast<std::size_t>(i)]["min"], par.min, what + " min");
      expectNumber(jb["parameters"][static_cast<std::size_t>(i)]["max"], par.max, what + " max");
    }
    const NearestPose n = nearestOnBranch(s.branches[b], p.mobile.pose);
    expectPose(jb["nearest"], n.pose, n.parameters, m.dof(), what + " nearest");
    expectNumber(jb["nearest"]["distance"], n.distance, what + " distance");
    EXPECT_EQ(jb["nearest_global"], n.global) << what;
    if (opt.samples > 0) {
      ASSERT_EQ(jb["samples"].size(), static_cast<std::size_t>(opt.samples)) << what;
      for (int k = 0; k < opt.samples; ++k) {
        const Params t = sampleParameters(m, n.parameters, opt.window, rng);
        expectPose(jb["samples"][static_cast<std::size_t>(k)], m.pose(t), t, m.dof(),
                   what + " sample");
      }
    }
  }
}

TEST(ResultLine, EveryNumberReadsBackAsWrittenForEveryBundledSpec) {
  const auto problems = bundledProblems();
  ASSERT_GT(problems.size(), 150u);
  ReportOptions with_samples;
  with_samples.samples = 3;
  with_samples.seed = 5;
  for (const Problem& p : problems) {
    expectLine(p, ReportOptions());
    expectLine(p, with_samples);
  }
}

// The number text the line holds for `v` (written as the solve time of a solution without
// branches: the cheapest line).
std::string numberText(double v) {
  Solution s;
  s.solve_us = v;
  std::string line;
  writeResultLine(bundledProblems().front(), s, ReportOptions(), line);
  const std::string key = "\"solve_us\":";
  const std::size_t at = line.rfind(key) + key.size();
  return line.substr(at, line.rfind("}}") - at);
}

// The shortest %e form that reads back as v: the fewest significant digits, tried one by one
// (printf rounds correctly).
std::string shortestScientific(double v) {
  char buf[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, v);
    if (sameDouble(std::strtod(buf, nullptr), v)) break;
  }
  return buf;
}

// A branch the numeric stage found (tests/support/test_fallback.hpp) is written "exact": false with
// its certificate right after "manifold", and the result's "complete" right after "status", in
// the line and the indented document alike: every value reads back as the Report's.
TEST(ResultLine, ACertifiedBranchAndCompletenessRoundTripInBothLayouts) {
  TestFallback stage;
  stage.pose = platformPose();
  stage.certificate = {1.0 / 3.0 * 1e-10, 2.5e-13};  // digits the two spellings write differently
  for (bool complete : {true, false}) {
    stage.complete = complete;
    const Registry reg = builtinsWithFallback(stage);
    const Problem p = platformProblem(stage.pose);
    const Solution s = solve(p, reg);
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    const Report report = evaluate(p, s, ReportOptions());
    ASSERT_EQ(report.branches.size(), 1u);
    EXPECT_FALSE(report.branches[0].exact);
    EXPECT_EQ(report.complete, complete);
    for (ResultFormat format : {kResultLine, kCollisionLine, kResultDocument}) {
      std::string text;
      writeReport(report, format, text);
      const json doc = json::parse(text);
      EXPECT_EQ(keysOf(doc, 6), "relpos name status complete isolated_complete message ") << text;
      EXPECT_EQ(doc["complete"], complete) << text;
      const json& b = doc["branches"][0];
      EXPECT_EQ(keysOf(b, 7),
                "dof rotational_dof translational_dof manifold exact certified parameters ")
          << text;
      EXPECT_EQ(b["exact"], false) << text;
      EXPECT_EQ(keysOf(b["certified"]), "radius angle ") << text;
      expectNumber(b["certified"]["radius"], stage.certificate.radius, "radius");
      expectNumber(b["certified"]["angle"], stage.certificate.angle, "angle");
      expectPose(b["nearest"], stage.pose, Params{}, 0, "the certified pose");
    }
  }
}

// What the rules leave (no numeric stage registered) is written incomplete, without branches.
TEST(ResultLine, AnUnhandledResultIsNotComplete) {
  const Problem p = platformProblem(platformPose());
  const Solution s = solve(p, rulesOnlyRegistry());
  ASSERT_EQ(s.status, Status::kUnhandled);
  for (ResultFormat format : {kResultLine, kResultDocument}) {
    std::string text;
    writeReport(evaluate(p, s, ReportOptions()), format, text);
    const json doc = json::parse(text);
    EXPECT_EQ(doc["status"], "unhandled");
    EXPECT_EQ(doc["complete"], false);
    EXPECT_TRUE(doc["branches"].empty());
  }
}

TEST(ResultLine, NumbersAreTheShortestTextThatReadsBackExactly) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                100.0,
                                0.1,
                                1.0 / 3.0,
                                1e-7,
                                1e21,
                                1e22,
                                123456789012345680000.0,
                                9007199254740992.0,
                                9007199254740994.0,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::epsilon()};
  std::mt19937_64 rng(13);
  while (values.size() < 3000) {  // every exponent, subnormals included: random bit patterns
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  for (int i = 0; i < 300; ++i) values.push_back(static_cast<double>(i) * 0.25 - 30.0);
  for (double v : values) {
    const std::string t = numberText(v);
    const double back = std::strtod(t.c_str(), nullptr);
    EXPECT_TRUE(sameDouble(back, v)) << t << " reads back as " << back;
    EXPECT_NE(t.find_first_of(".e"), std::string::npos) << t << ": not written as a float";
    // Shortest: no longer than the shortest %e form (the ".0" a float needs aside; a fixed form
    // is chosen when it is no longer, as in 123456789012345683968.0).
    const std::string core =
        t.size() > 2 && t.compare(t.size() - 2, 2, ".0") == 0 && t.find('e') == std::string::npos
            ? t.substr(0, t.size() - 2)
            : t;
    EXPECT_LE(core.size(), shortestScientific(v).size()) << t << " vs " << shortestScientific(v);
    // relpos reads its own output exactly (the spec reader on the same text).
    const std::string spec = R"({"fixed": {"pose": {"position": [)" + t +
                             R"(, 0, 0]}, "features": {}}, "mobile": {"features": {}},
                             "constraints": []})";
    const ParseResult r = parseSpec(spec, builtinRegistry());
    ASSERT_TRUE(r.problem) << spec;
    EXPECT_TRUE(sameDouble(r.problem->fixed.pose.translation().x(), v)) << t;
  }
  // Not a number: null.
  EXPECT_EQ(numberText(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(numberText(std::numeric_limits<double>::infinity()), "null");
}

TEST(ResultLine, NamesAreEscapedAsJsonNeeds) {
  Problem p = bundledProblems().front();
  for (const char* name : {"quote \" and \\ backslash", "tab\tnew\nline\r", "bell \x07 \x1f \x7f",
                           "caf\xc3\xa9 \xe2\x9c\x93", "/slash/", "\xf0\x9f\x98\x80"}) {
    p.name = name;
    const Solution s = solve(p, builtinRegistry());
    std::string line;
    writeResultLine(p, s, ReportOptions(), line);
    for (char c : line) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << "raw control in " << line;
    const json doc = json::parse(line);
    EXPECT_EQ(doc["name"], name);
    EXPECT_EQ(doc, documentTree(p, s, ReportOptions()));
  }
}

// A name that is not UTF-8 (a default name from a file name, or one set through the API): each
// ill-formed part becomes one U+FFFD, as Unicode recommends ("maximal subparts", Unicode 15
// §3.9, table 3-8), so the line stays valid UTF-8 and a JSON library can parse it.
TEST(ResultLine, BytesThatAreNotUtf8BecomeReplacementCharacters) {
  const std::string r = "\xef\xbf\xbd";  // U+FFFD
  const std::pair<std::string, std::string> cases[] = {
      {"\xff", r},
      {"spec\xff", "spec" + r},
      {"caf\xc3", "caf" + r},                             // cut before its last byte
      {"\xe2\x9c", r},                                    // one maximal subpart: one U+FFFD
      {"\xe2\x9c\x93", "\xe2\x9c\x93"},                   // well-formed (U+2713)
      {"\xed\xa0\x80", r + r + r},                        // an encoded surrogate: ED, A0, 80
      {"\xc0\xaf", r + r},                                // an overlong form
      {"a\xf4\x90\x80\x80z", "a" + r + r + r + r + "z"},  // beyond U+10FFFF
      {"\x80 stray", r + " stray"},
  };
  Problem p = bundledProblems().front();
  const Solution s = solve(p, builtinRegistry());
  for (const auto& [name, expected] : cases) {
    p.name = name;
    std::string line;
    writeResultLine(p, s, ReportOptions(), line);
    json doc;
    ASSERT_NO_THROW(doc = json::parse(line)) << line;
    EXPECT_EQ(doc["name"], expected);
    json tree;
    ASSERT_NO_THROW(tree = documentTree(p, s, ReportOptions()));
    EXPECT_EQ(tree["name"], expected);
    EXPECT_NO_THROW((void)tree.dump());
  }
}

}  // namespace
}  // namespace relpos::test
