// One problem per rule case (data/rules, expectations in data/expected/rules.json, each derived
// by hand from the geometry): the case fires, and the answer has the expected status, branches,
// DOF, conflicts and redundant constraints, with every sampled pose satisfying every input.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "relpos/core/spec_io.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

TEST(RuleCases, EachCaseFiresWithTheExpectedAnswer) {
  std::ifstream in(RELPOS_DATA_DIR "/expected/rules.json");
  ASSERT_TRUE(in);
  const nlohmann::json expected = nlohmann::json::parse(in);
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(RELPOS_DATA_DIR "/rules")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
    ASSERT_TRUE(r.problem);
    ASSERT_TRUE(expected.contains(r.problem->name));
    const auto& x = expected[r.problem->name];
    Solution s = solve(*r.problem, builtinRegistry());
    const std::string want = x["fires"];
    EXPECT_TRUE(std::any_of(s.rules.begin(), s.rules.end(),
                            [&](const char* f) { return want == f; }))
        << want << " did not fire; fired: " << [&] {
             std::string all;
             for (const char* f : s.rules) all += std::string(f) + " ";
             return all;
           }();
    EXPECT_EQ(toString(s.status), x["status"].get<std::string>()) << describeBranches(s);
    std::vector<int> dofs, dof_want = x["dof"].get<std::vector<int>>();
    for (const auto& b : s.branches) dofs.push_back(b.manifold->dof());
    std::sort(dofs.begin(), dofs.end());
    std::sort(dof_want.begin(), dof_want.end());
    EXPECT_EQ(dofs, dof_want) << describeBranches(s);
    if (x.contains("conflicts")) {
      EXPECT_EQ(s.conflicts, x["conflicts"].get<std::vector<int>>());
    }
    if (x.contains("redundant")) {
      EXPECT_EQ(s.redundant, x["redundant"].get<std::vector<int>>());
    }
    std::string where;
    EXPECT_LT(worstSampledViolation(*r.problem, s, 200, 3, &where), 1e-9) << where;
    ++n;
  }
  EXPECT_EQ(n, static_cast<int>(expected.size()));
}

}  // namespace
}  // namespace relpos::test
