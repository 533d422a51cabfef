// The manifold conformance suite (STYLE.md §10): every manifold the solver can produce — every
// branch of every example and of random single-constraint problems — passes the same property
// checks: poses are rigid, pose(project(pose(θ))) == pose(θ), contains() holds on the manifold,
// parameters are well formed and respected, nearest is never worse than the projection.
#include "relpos/plugins/conformance.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

// The installed conformance kit's manifold suite (the one plugin authors run).
void expectManifoldInvariants(const Manifold& m, std::uint64_t seed, const std::string& label) {
  plugins::Report report;
  plugins::checkManifold(m, seed, report);
  EXPECT_TRUE(report.ok()) << label << ":\n" << report.text();
  EXPECT_GT(report.checked, 0) << label;
}

TEST(ManifoldConformance, EveryBundledBranch) {
  int n = 0;
  for (const char* dir :
       {RELPOS_DATA_DIR "/examples", RELPOS_DATA_DIR "/scenarios", RELPOS_DATA_DIR "/rules"})
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      ASSERT_TRUE(r.problem);
      Solution s = solve(*r.problem, builtinRegistry());
      for (const Branch& b : s.branches)
        expectManifoldInvariants(*b.manifold, ++n, e.path().stem());
    }
  EXPECT_GT(n, 40);
}

TEST(ManifoldConformance, RandomSingleConstraintBranches) {
  Rng rng(31337);
  int n = 0;
  for (const SingleKind& kind : singleKinds())
    for (int k = 0; k < 3; ++k) {
      KnownProblem kp = emptyKnownProblem(rng, k == 2);
      addConstraint(kp, kind, rng, k == 2);
      Solution s = solve(kp.problem, builtinRegistry());
      for (const Branch& b : s.branches) expectManifoldInvariants(*b.manifold, ++n, kind.label);
    }
  EXPECT_GT(n, 100);
}

TEST(ManifoldConformance, BranchesCopyWithTheirManifold) {
  ParseResult r =
      parseSpecFile(RELPOS_DATA_DIR "/examples/pmf-simple-example.json", builtinRegistry());
  Solution s = solve(*r.problem, builtinRegistry());
  ASSERT_EQ(s.branches.size(), 1u);
  Branch copy = s.branches[0];
  s.branches.clear();
  Params t{};
  t[0] = 0.7;
  EXPECT_EQ(copy.manifold->dof(), 1);
  EXPECT_TRUE(copy.manifold->pose(t).translation().allFinite());
}

}  // namespace
}  // namespace relpos::test
