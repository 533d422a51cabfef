// One problem per rule case: data/rules/FAMILY--CASE.json, its answer derived by hand from the
// geometry beside it in FAMILY--CASE.expected. Each is its own test, named after the spec
// (--gtest_filter='DataRules/RuleCaseSpec.*/pp_pplane__circle' runs
// data/rules/pp_pplane--circle.json alone): the case fires, and the answer has the expected status,
// branches, DOF, conflicts and redundant constraints, with every sampled pose satisfying every
// input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "expected_results.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/rules/builtin.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;
const std::string kDir = RELPOS_DATA_DIR "/rules/";

// The stems of data/rules/*.json (and of *.expected with `extension` ".expected"), sorted.
std::vector<std::string> stems(const std::string& extension) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(kDir))
    if (e.path().extension() == extension) out.push_back(e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

// A test name from a spec's stem: gtest takes letters, digits and '_' only ('-' becomes '_').
std::string testName(const testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

class RuleCaseSpec : public testing::TestWithParam<std::string> {};

TEST_P(RuleCaseSpec, FiresWithTheExpectedAnswer) {
  const std::string stem = GetParam();
  // The spec is named as the case it covers is spelled for files (fileSpelling).
  std::ifstream in(kDir + stem + ".expected");
  ASSERT_TRUE(in) << "no expectation beside " << stem << ".json";
  const nlohmann::json expected = nlohmann::json::parse(in);
  ASSERT_TRUE(expected.contains("fires")) << "a rule case's expectation names the case it fires";
  EXPECT_EQ(rules::fileSpelling(expected["fires"].get<std::string>()), stem);
  checkSpecAgainstExpectation(kDir + stem + ".json", kDir + stem + ".expected", builtinRegistry());
}

INSTANTIATE_TEST_SUITE_P(DataRules, RuleCaseSpec, testing::ValuesIn(stems(".json")), testName);

// One spec per case: a case without data/rules/FAMILY--CASE.json fails here.
TEST(RuleCases, EveryRegisteredCaseHasItsDataSpec) {
  const std::vector<std::string> specs = stems(".json");
  for (const RuleInfo& rule : builtinRegistry().rules())
    for (const RuleCase& c : rule.cases)
      EXPECT_TRUE(std::binary_search(specs.begin(), specs.end(), rules::fileSpelling(c.name)))
          << "no data/rules/" << rules::fileSpelling(c.name) << ".json for " << c.name;
}

TEST(RuleCases, EveryExpectationHasItsSpec) {
  const std::vector<std::string> specs = stems(".json");
  for (const std::string& stem : stems(".expected"))
    EXPECT_TRUE(std::binary_search(specs.begin(), specs.end(), stem)) << stem << ".expected";
  EXPECT_GT(specs.size(), 30u);
}

}  // namespace
}  // namespace relpos::test
