// One problem per rule case (data/rules, expectations in data/expected/rules.json, each derived
// by hand from the geometry): the case fires, and the answer has the expected status, branches,
// DOF, conflicts and redundant constraints, with every sampled pose satisfying every input.
#include <gtest/gtest.h>

#include "expected_results.hpp"

namespace relpos::test {
namespace {

TEST(RuleCases, EachCaseFiresWithTheExpectedAnswer) {
  EXPECT_GT(checkFolderAgainstExpectations("rules", "rules.json"), 30);
}

}  // namespace
}  // namespace relpos::test
