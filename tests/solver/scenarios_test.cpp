// Somani et al.'s application scenarios (004 §VI) as specs in data/scenarios, each checked against
// its hand-derived status and DOF, with every sampled pose satisfying every input constraint.
#include <gtest/gtest.h>

#include "expected_results.hpp"

namespace relpos::test {
namespace {

TEST(Scenarios, MatchExpectedStatusAndDof) {
  EXPECT_EQ(checkFolderAgainstExpectations("scenarios", "scenarios.json"), 5);
}

}  // namespace
}  // namespace relpos::test
