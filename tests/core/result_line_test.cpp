// The result line (writeResultLine) is the JSON document SPEC.md §2 describes, in exactly the
// text nlohmann's dump() gives it: parsing it and dumping it again changes nothing, for every
// bundled spec (with and without samples) and for names that need escaping.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "relpos/core/solver.hpp"
#include "relpos/core/spec_io.hpp"
#include "relpos/rules/builtin.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

std::vector<Problem> bundledProblems() {
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

void expectCanonical(const Problem& p, const ResultOptions& opt) {
  const Solution s = solve(p, builtinRegistry());
  std::string line;
  writeResultLine(p, s, opt, line);
  const auto doc = nlohmann::ordered_json::parse(line);  // throws on malformed JSON
  EXPECT_EQ(doc.dump(), line) << p.name;
  EXPECT_EQ(doc["name"], p.name);
  EXPECT_EQ(doc["branches"].size(), s.branches.size());
  for (const auto& b : doc["branches"]) {
    EXPECT_EQ(b["parameters"].size(), b["dof"].get<std::size_t>());
    EXPECT_EQ(b["nearest"]["position"].size(), 3u);
    if (opt.samples > 0) {
      EXPECT_EQ(b["samples"].size(), static_cast<std::size_t>(opt.samples));
    }
  }
}

TEST(ResultLine, IsNlohmannCanonicalJsonForEveryBundledSpec) {
  const auto problems = bundledProblems();
  ASSERT_GT(problems.size(), 150u);
  ResultOptions with_samples;
  with_samples.samples = 3;
  with_samples.seed = 5;
  for (const Problem& p : problems) {
    expectCanonical(p, ResultOptions());
    expectCanonical(p, with_samples);
  }
}

TEST(ResultLine, EscapesNamesLikeTheJsonLibrary) {
  Problem p = bundledProblems().front();
  for (const char* name : {"quote \" and \\ backslash", "tab\tnew\nline\r", "bell \x07 \x1f",
                           "caf\xc3\xa9 \xe2\x9c\x93", "/slash/"}) {
    p.name = name;
    expectCanonical(p, ResultOptions());
  }
}

}  // namespace
}  // namespace relpos::test
