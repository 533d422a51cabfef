// Every spec in data/examples: status, branch count and DOF as listed in
// data/expected/examples.json (derived by hand from the geometry), and every sampled pose of every
// branch satisfies every input constraint.
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

namespace fs = std::filesystem;

TEST(Examples, MatchExpectedStatusAndDof) {
  std::ifstream in(RELPOS_DATA_DIR "/expected/examples.json");
  ASSERT_TRUE(in) << "missing data/expected/examples.json";
  nlohmann::json expected = nlohmann::json::parse(in);
  int checked = 0;
  for (const auto& e : fs::directory_iterator(RELPOS_DATA_DIR "/examples")) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
    ASSERT_TRUE(r.problem) << r.errors.front().message;
    ASSERT_TRUE(expected.contains(r.problem->name)) << "no expectation for " << r.problem->name;
    const auto& x = expected[r.problem->name];
    Solution s = solve(*r.problem, builtinRegistry());
    EXPECT_EQ(toString(s.status), x["status"].get<std::string>()) << describeBranches(s);
    EXPECT_EQ(s.branches.size(), x["branches"].get<std::size_t>()) << describeBranches(s);
    std::vector<int> dofs, want = x["dof"].get<std::vector<int>>();
    for (const auto& b : s.branches) dofs.push_back(b.manifold->dof());
    std::sort(dofs.begin(), dofs.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(dofs, want) << describeBranches(s);
    if (x.contains("redundant")) {
      EXPECT_EQ(s.redundant, x["redundant"].get<std::vector<int>>());
    }
    if (x.contains("conflicts")) {
      EXPECT_EQ(s.conflicts, x["conflicts"].get<std::vector<int>>());
    }
    std::string where;
    EXPECT_LT(worstSampledViolation(*r.problem, s, 200, 7, &where), 1e-9) << where;
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(expected.size())) << "every expectation has its spec";
}

}  // namespace
}  // namespace relpos::test
