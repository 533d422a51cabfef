// Permuting the input constraints gives the same solution set: same status, the same number of
// branches with the same DOF, and every sampled pose of one answer lies on a branch of the other.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "random_problems.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

std::vector<int> dofs(const Solution& s) {
  std::vector<int> d;
  for (const auto& b : s.branches) d.push_back(b.manifold->dof());
  std::sort(d.begin(), d.end());
  return d;
}

void expectSameSet(const Solution& a, const Solution& b, std::mt19937_64& rng) {
  for (const Branch& br : a.branches)
    for (int k = 0; k < 8; ++k) {
      Isometry3d X = br.manifold->pose(sampleParams(*br.manifold, rng));
      EXPECT_TRUE(someBranchContains(b, X, 1e-6)) << poseText(X) << "\n" << describeBranches(b);
    }
}

TEST(OrderInvariance, PermutedConstraintsSameSolutionSet) {
  Rng rng(777);
  std::mt19937_64 sampler(778);
  const auto& kinds = singleKinds();
  int compared = 0;
  for (int trial = 0; trial < 300 && compared < 120; ++trial) {
    KnownProblem kp = emptyKnownProblem(rng, trial % 2 == 1);
    NamedFeature shared;
    const int n = rng.integer(2, 3);
    for (int k = 0; k < n; ++k) {
      addConstraint(kp, kinds[rng.integer(0, static_cast<int>(kinds.size()) - 1)], rng,
                    trial % 2 == 1, k && trial % 3 ? &shared : nullptr);
      if (k == 0) shared = kp.problem.mobile.features.back();
    }
    Solution base = solve(kp.problem, builtinRegistry());
    if (base.status != Status::kSolved) continue;
    std::vector<int> perm(n);
    std::iota(perm.begin(), perm.end(), 0);
    while (std::next_permutation(perm.begin(), perm.end())) {
      Problem p = kp.problem;
      for (int k = 0; k < n; ++k) p.constraints[k] = kp.problem.constraints[perm[k]];
      Solution s = solve(p, builtinRegistry());
      SCOPED_TRACE("trial " + std::to_string(trial));
      ASSERT_EQ(s.status, base.status) << s.message;
      EXPECT_EQ(dofs(s), dofs(base)) << describeBranches(s) << "\nvs\n" << describeBranches(base);
      expectSameSet(base, s, sampler);
      expectSameSet(s, base, sampler);
    }
    ++compared;
  }
  EXPECT_GE(compared, 60) << "too few solved problems to compare";
}

}  // namespace
}  // namespace relpos::test
