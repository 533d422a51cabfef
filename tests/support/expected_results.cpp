#include "expected_results.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {

namespace {

std::string firedList(const Solution& s) {
  std::string all;
  for (const char* f : s.ruleNames()) all += std::string(f) + " ";
  return all;
}

void checkOne(const Problem& p, const nlohmann::json& x, const Registry& registry) {
  Solution s = solve(p, registry);
  if (x.contains("fires")) {
    const std::string want = x["fires"];
    EXPECT_TRUE(std::any_of(s.ruleNames().begin(), s.ruleNames().end(),
                            [&](const char* f) { return want == f; }))
        << want << " did not fire; fired: " << firedList(s);
  }
  EXPECT_EQ(toString(s.status), x["status"].get<std::string>()) << describeBranches(s);
  // docs/spec.md §2.2: an unhandled answer is never complete, an inconsistent one always; the
  // rules' closed forms (no numeric stage registered) enumerate every branch, each exact.
  if (s.status == Status::kUnhandled) {
    EXPECT_FALSE(s.complete);
  }
  if (s.status == Status::kInconsistent) {
    EXPECT_TRUE(s.complete);
  }
  if (!registry.fallback()) {
    EXPECT_EQ(s.complete, s.status == Status::kSolved || s.status == Status::kInconsistent);
    for (const Branch& b : s.branches) EXPECT_TRUE(b.exact) << describeBranches(s);
  }
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
  EXPECT_LT(worstSampledViolation(p, s, 200, 7, &where), 1e-9) << where;
}

}  // namespace

int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file,
                                   const Registry& registry) {
  std::ifstream in(std::string(RELPOS_DATA_DIR) + "/expected/" + expected_file);
  EXPECT_TRUE(in) << "missing data/expected/" << expected_file;
  if (!in) return 0;
  const nlohmann::json expected = nlohmann::json::parse(in);
  int checked = 0;
  for (const auto& e :
       std::filesystem::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder)) {
    if (e.path().extension() != ".json") continue;
    SCOPED_TRACE(e.path().string());
    ParseResult r = parseSpecFile(e.path().string(), registry);
    EXPECT_TRUE(r.problem) << (r.errors.empty() ? "" : r.errors.front().message);
    if (!r.problem) continue;
    EXPECT_TRUE(expected.contains(r.problem->name)) << "no expectation for " << r.problem->name;
    if (!expected.contains(r.problem->name)) continue;
    checkOne(*r.problem, expected[r.problem->name], registry);
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(expected.size())) << "every expectation has its spec";
  return checked;
}

int checkFolderAgainstExpectations(const std::string& folder, const std::string& expected_file) {
  return checkFolderAgainstExpectations(folder, expected_file, builtinRegistry());
}

void checkSpecAgainstExpectation(const std::string& spec_path, const std::string& expected_path,
                                 const Registry& registry) {
  std::ifstream in(expected_path);
  ASSERT_TRUE(in) << "missing " << expected_path;
  const nlohmann::json expected = nlohmann::json::parse(in);
  ParseResult r = parseSpecFile(spec_path, registry);
  ASSERT_TRUE(r.problem) << (r.errors.empty() ? "" : r.errors.front().message);
  checkOne(*r.problem, expected, registry);
}

}  // namespace relpos::test
