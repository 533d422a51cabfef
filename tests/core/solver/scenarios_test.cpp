// Somani et al.'s application scenarios (004 §VI) as specs in data/scenarios, each checked against
// its hand-derived status and DOF, with every sampled pose satisfying every input constraint.
#include <gtest/gtest.h>

#include "expected_results.hpp"

namespace relpos::test {
namespace {

TEST(Scenarios, MatchExpectedStatusAndDof) {
  EXPECT_EQ(checkFolderAgainstExpectations("scenarios", "scenarios.json"), 8);
}

}  // namespace
}  // namespace relpos::test

#include <random>

#include "evaluator.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

Problem loadScenario(const char* name) {
  ParseResult r =
      parseSpecFile(std::string(RELPOS_DATA_DIR) + "/scenarios/" + name, builtinRegistry());
  EXPECT_TRUE(r.problem);
  return *r.problem;
}

// Somani §VI-E (scenario F): three problems solved in sequence, each solution placing the fixed
// object of the next one: tray in the world (4 DOF) → housing on the tray (3) → shaft in the
// housing (1): 8 DOF in all. Every combination of parameters gives world poses that satisfy all
// constraints of all three problems.
TEST(Scenarios, TrayCarryingChainsThreeProblems) {
  Problem tray = loadScenario("scenario-f1-tray-in-world.json");
  Problem housing = loadScenario("scenario-f2-part-on-tray.json");
  Problem shaft = loadScenario("scenario-f3-shaft-in-housing.json");
  std::mt19937_64 rng(8);
  const Solution s1 = solve(tray, builtinRegistry());
  ASSERT_EQ(s1.status, Status::kSolved);
  int total_dof = 0;
  for (int k = 0; k < 20; ++k) {
    const Branch& b1 = s1.branches[0];
    const Isometry3d X_W_tray = b1.manifold->pose(sampleParams(*b1.manifold, rng));
    ASSERT_LT(worstViolation(tray, X_W_tray), 1e-9);
    housing.fixed.pose = X_W_tray;  // the output of step 1 is the input of step 2
    const Solution s2 = solve(housing, builtinRegistry());
    ASSERT_EQ(s2.status, Status::kSolved) << s2.message;
    const Isometry3d X_W_housing =
        s2.branches[0].manifold->pose(sampleParams(*s2.branches[0].manifold, rng));
    ASSERT_LT(worstViolation(housing, X_W_housing), 1e-9);
    shaft.fixed.pose = X_W_housing;  // and the output of step 2 the input of step 3
    const Solution s3 = solve(shaft, builtinRegistry());
    ASSERT_EQ(s3.status, Status::kSolved) << s3.message;
    ASSERT_EQ(s3.branches.size(), 1u);
    const Isometry3d X_W_shaft =
        s3.branches[0].manifold->pose(sampleParams(*s3.branches[0].manifold, rng));
    EXPECT_LT(worstViolation(shaft, X_W_shaft), 1e-9);
    // The tray stays level whatever the other steps do: the shaft's axis stays vertical.
    EXPECT_NEAR(std::abs((X_W_shaft.linear() * Vector3d::UnitZ()).z()), 1.0, 1e-9);
    total_dof =
        b1.manifold->dof() + s2.branches[0].manifold->dof() + s3.branches[0].manifold->dof();
  }
  EXPECT_EQ(total_dof, 8);
}

}  // namespace
}  // namespace relpos::test
