// The fuzzing checks checked on their own: each flags what it is there to flag (a checker that
// flags nothing would let the mutation test and the fuzzer pass whatever relpos does), and the
// mutator is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "known_failures.hpp"
#include "mutator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "result_checks.hpp"
#include "test_config.hpp"

namespace relpos::fuzz {
namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The pmf worked example (one 1-DOF branch), parsed, solved and written with 3 samples.
struct Written {
  Problem problem;
  std::string line;
};
Written workedExample() {
  ParseResult r =
      parseSpec(slurp(RELPOS_DATA_DIR "/examples/pmf-simple-example.json"), builtinRegistry(), "x");
  EXPECT_TRUE(r.problem);
  Written w{*r.problem, ""};
  const Solution s = solve(w.problem, builtinRegistry());
  ReportOptions o;
  o.samples = 3;
  writeResultLine(w.problem, s, o, w.line);
  return w;
}

std::vector<std::string> kinds(const Findings& f) {
  std::vector<std::string> k;
  for (const Finding& x : f) k.push_back(x.kind);
  return k;
}

Findings check(const Written& w, const std::string& line) {
  Findings f;
  ResultExpectation e;
  e.samples = 3;
  checkResultText(line, w.problem, e, f);
  return f;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

TEST(FuzzChecks, ACorrectResultPasses) {
  const Written w = workedExample();
  EXPECT_TRUE(check(w, w.line).empty()) << kinds(check(w, w.line))[0];
}

TEST(FuzzChecks, AMovedPoseIsAWrongAnswer) {
  const Written w = workedExample();
  // The nearest pose's x moved by 1e-3 (the problem's size is 7: 1.4e-4 of it, above 1e-6).
  const std::string at = "\"position\":[";
  const std::size_t from = w.line.find(at) + at.size(), to = w.line.find(',', from);
  const double x = std::stod(w.line.substr(from, to - from));
  char moved[40];
  std::snprintf(moved, sizeof moved, "%.17g", x + 1e-3);
  const auto k = kinds(check(w, w.line.substr(0, from) + moved + w.line.substr(to)));
  EXPECT_NE(std::find(k.begin(), k.end(), "wrong-answer"), k.end());
}

TEST(FuzzChecks, ANullWhereSpecHasANumberIsBadOutput) {
  const Written w = workedExample();
  const auto k = kinds(check(w, replaced(w.line, "\"parameters\":[", "\"parameters\":[null,")));
  EXPECT_NE(std::find(k.begin(), k.end(), "bad-output"), k.end());
  // A null bound on an angle (SPEC allows it on unbounded lengths only).
  const auto a = kinds(check(w, replaced(w.line, "\"min\":-3.141592653589793", "\"min\":null")));
  EXPECT_NE(std::find(a.begin(), a.end(), "bad-output"), a.end());
}

TEST(FuzzChecks, TextThatIsNotOneUtf8JsonDocumentIsBadOutput) {
  const Written w = workedExample();
  for (const std::string& bad : {w.line + "x", w.line.substr(0, w.line.size() - 1),
                                 replaced(w.line, "\"name\":\"", "\"name\":\"\xFF"),
                                 replaced(w.line, "\"message\":\"", "\"message\":\"\xC0\x80")}) {
    const auto k = kinds(check(w, bad));
    EXPECT_NE(std::find(k.begin(), k.end(), "bad-output"), k.end()) << printable(bad, 80);
  }
}

TEST(FuzzChecks, BranchesOfAResultThatIsNotSolvedAreBadOutput) {
  const Written w = workedExample();
  const auto k =
      kinds(check(w, replaced(w.line, "\"status\":\"solved\"", "\"status\":\"unhandled\"")));
  EXPECT_NE(std::find(k.begin(), k.end(), "bad-output"), k.end());
}

// "complete" and "exact"/"certified" (docs/spec.md §2.2, §2.4): each misuse is flagged.
TEST(FuzzChecks, CompletenessAndCertificatesThatContradictTheResultAreBadOutput) {
  const Written w = workedExample();
  const auto flagged = [&](const std::string& line) {
    const auto k = kinds(check(w, line));
    return std::find(k.begin(), k.end(), "bad-output") != k.end();
  };
  EXPECT_TRUE(flagged(replaced(w.line, "\"complete\":true,", "")));
  EXPECT_TRUE(flagged(replaced(w.line, "\"exact\":true", "\"exact\":false")));
  EXPECT_TRUE(flagged(replaced(w.line, "\"exact\":true",
                               "\"exact\":true,\"certified\":{\"radius\":0.0,\"angle\":0.0}")));
  EXPECT_TRUE(flagged(replaced(w.line, "\"exact\":true",
                               "\"exact\":false,\"certified\":{\"radius\":-1.0,\"angle\":0.0}")));
  EXPECT_FALSE(flagged(replaced(w.line, "\"exact\":true",
                                "\"exact\":false,\"certified\":{\"radius\":1e-12,\"angle\":0.0}")));
  // An unhandled result that claims completeness.
  const std::string unhandled =
      replaced(replaced(w.line, "\"status\":\"solved\"", "\"status\":\"unhandled\""),
               "\"message\":\"\"", "\"message\":\"why\"");
  const std::size_t from = unhandled.find("\"branches\":[") + 12, to = unhandled.find("],\"best\"");
  const std::string no_branches =
      replaced(unhandled.substr(0, from) + unhandled.substr(to), "\"best\":0", "\"best\":null");
  EXPECT_TRUE(flagged(no_branches));
  const std::string not_complete = replaced(no_branches, "\"complete\":true", "\"complete\":false");
  // isolated_complete too (implied by complete; never for unhandled).
  EXPECT_TRUE(flagged(not_complete));
  EXPECT_FALSE(
      flagged(replaced(not_complete, "\"isolated_complete\":true", "\"isolated_complete\":false")));
}

TEST(FuzzChecks, DiagnosticsMustBeOneLineWithAPath) {
  ParseResult r;
  r.errors.push_back({"constraints[0]", "one\ntwo"});
  r.errors.push_back({"", "unknown field (ignored)"});
  r.errors.push_back({"", "the spec must be a JSON object"});
  r.errors.push_back({"", "malformed JSON at line 3, column 14: unexpected '}'"});
  Findings f;
  checkDiagnostics(r, f);
  ASSERT_EQ(kinds(f), (std::vector<std::string>{"split-diagnostic", "pathless-message"}));
  EXPECT_TRUE(namesTheDocument("malformed JSON at line 1, column 1"));
  EXPECT_TRUE(namesTheDocument("too deeply nested at line 1, column 1025: more than 1024 …"));
  EXPECT_TRUE(namesTheDocument("the spec must be a JSON object"));
  EXPECT_FALSE(namesTheDocument("malformed JSON: number overflow parsing '1e400'"));
  EXPECT_FALSE(namesTheDocument("malformed JSON at line , column 1"));
  EXPECT_FALSE(namesTheDocument("unknown field (ignored)"));
  // The fuzzer's find: the document "1e400" (a root number beyond a double's range).
  EXPECT_TRUE(namesTheDocument("number out of the range of a double '1e400' (line 1, column 1)"));
  EXPECT_FALSE(namesTheDocument("number out of the range of a double '1e400' (line 1)"));
  EXPECT_FALSE(namesTheDocument("number out of the range (line 1, column 1) of a double"));
}

TEST(FuzzChecks, AnAcceptedDocumentHoldingANulOrInvalidUtf8IsFlagged) {
  ParseResult ok;
  ok.problem = Problem();
  for (const std::string& text : {std::string("{}\0x", 4), std::string("{\"a\":\"\xFF\"}"),
                                  std::string("{\"a\":\"\x01\"}")}) {
    Findings f;
    checkAccepted(text, ok, f);
    EXPECT_EQ(kinds(f), std::vector<std::string>{"accepted-invalid-json"}) << printable(text);
  }
  Findings none;
  checkAccepted("{\"a\":\"\xC3\xA9\"}\n\t\r", ok, none);
  EXPECT_TRUE(none.empty());
}

TEST(FuzzChecks, Utf8Validation) {
  EXPECT_TRUE(isValidUtf8("a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80"));
  for (const char* bad : {"\xFF", "\xC3", "\xC0\x80", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\x80"})
    EXPECT_FALSE(isValidUtf8(bad)) << printable(bad);
}

TEST(FuzzChecks, TheScaledProblemMeasuresLengthsInItsSize) {
  Problem p;
  p.addFixedFeature("a", Feature::makePoint({2000, 0, 0}));
  p.addMobileFeature("b", Feature::makePoint({0, 0, 0}));
  p.addConstraint("distance", "a", "b", 1000);
  EXPECT_EQ(problemSize(p), 2000);
  const Problem s = scaledProblem(p, 2000);
  EXPECT_EQ(s.constraints[0].fixed.point.x(), 1.0);
  EXPECT_EQ(s.constraints[0].value, 0.5);
}

TEST(FuzzMutator, TheSameSeedGivesTheSameMutants) {
  const std::vector<Seed> seeds = loadSeeds(RELPOS_DATA_DIR);
  ASSERT_FALSE(seeds.empty());
  MutationOptions o;
  o.one_line = true;
  Mutator a(5, o), b(5, o);
  for (int i = 0; i < 200; ++i) {
    const JsonNode& seed = seeds[static_cast<std::size_t>(i) % seeds.size()].tree;
    const std::string x = a.mutate(seed, "n"), y = b.mutate(seed, "n");
    ASSERT_EQ(x, y) << i;
    EXPECT_EQ(x.find('\n'), std::string::npos) << i;  // a JSONL line stays one line
  }
}

TEST(FuzzKnownFailures, MatchOnlyWhatTheyName) {
  // Only the listed failures are tolerated: a wrong answer on ordinary input is never "known",
  // nor are the failures main has fixed (deep nesting, pathless messages, a NUL in the text).
  EXPECT_EQ(knownFailure({"wrong-answer", "violates constraints[0]"}, "{\"relpos\":1}"), nullptr);
  EXPECT_EQ(knownFailure({"crash", "signal 11"}, std::string(300000, '[')), nullptr);
  EXPECT_EQ(knownFailure({"pathless-message", "no JSON path: '': 'unknown field (ignored)'"}, ""),
            nullptr);
  // The two fixed on main fail again: an initial pose beyond 1e100, a frame 1e15 away.
  const std::string huge = "{\"mobile\":{\"pose\":{\"position\":[-1e300,0,0]}}}";
  EXPECT_EQ(knownFailure({"bad-output", "/branches/0/nearest/distance: null"}, huge), nullptr);
  const std::string far = "/branches/0/nearest: violates constraints[1] (distance front palm) by ";
  EXPECT_EQ(knownFailure({"wrong-answer", far + "1.5 (relative to the problem's size 1e15)"}, ""),
            nullptr);
}

}  // namespace
}  // namespace relpos::fuzz
