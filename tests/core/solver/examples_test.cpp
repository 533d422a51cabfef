// Every spec in data/examples: status, branch count and DOF as listed in
// data/expected/examples.json (derived by hand from the geometry), and every sampled pose of every
// branch satisfies every input constraint.
#include <gtest/gtest.h>

#include "expected_results.hpp"

namespace relpos::test {
namespace {

TEST(Examples, MatchExpectedStatusAndDof) {
  EXPECT_GT(checkFolderAgainstExpectations("examples", "examples.json"), 50);
}

}  // namespace
}  // namespace relpos::test
