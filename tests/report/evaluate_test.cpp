// The report stage (report/src/evaluate.cpp) against what it promises, checked independently:
// the nearest pose is the branch's pose nearest the initial pose (no dense sample beats it), the
// samples lie on the branch (the tests' own evaluator of docs/spec.md §1), the best branch is the
// one nearest, and the collision verdicts agree with the scene.
#include "relpos/report/evaluate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "evaluator.hpp"
#include "relpos/collision/scene.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

struct Spec {
  std::string file;
  Problem problem;
};

std::vector<Spec> specsIn(const std::string& folder) {
  std::vector<Spec> specs;
  for (const auto& e : fs::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder))
    if (e.path().extension() == ".json") {
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      if (r.problem) specs.push_back({e.path().string(), std::move(*r.problem)});
    }
  return specs;
}

// The smallest pose distance to X over n parameter draws of the branch around `centre` (within
// the bounds; unbounded lengths within ±window of the centre's).
double bestOverDenseSamples(const Manifold& m, const Params& centre, const Isometry3d& X, int n,
                            double window) {
  std::mt19937_64 rng(12345);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k)
    best = std::min(best, poseDistance(m.pose(sampleParameters(m, centre, window, rng)), X));
  return best;
}

TEST(Evaluate, NearestIsTheBestPoseOfEachBranchAndSamplesLieOnIt) {
  ReportOptions options;
  options.samples = 16;
  options.seed = 3;
  int branches = 0;
  for (const char* folder : {"examples", "scenarios"})
    for (const Spec& spec : specsIn(folder)) {
      const Problem& p = spec.problem;
      const Solution s = solve(p, builtinRegistry());
      const Report r = evaluate(p, s, options);
      ASSERT_EQ(r.branches.size(), s.branches.size()) << spec.file;
      EXPECT_EQ(r.status, s.status) << spec.file;
      EXPECT_EQ(r.name, p.name);
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t b = 0; b < s.branches.size(); ++b, ++branches) {
        const Manifold& m = *s.branches[b].manifold;
        const BranchReport& br = r.branches[b];
        const std::string what = spec.file + " branch " + std::to_string(b);
        EXPECT_EQ(br.dof, m.dof()) << what;
        // The nearest pose is a pose of the branch, at the distance it claims...
        EXPECT_TRUE(m.pose(br.nearest.parameters).isApprox(br.nearest.pose, 1e-12)) << what;
        EXPECT_NEAR(br.nearest.distance, poseDistance(br.nearest.pose, p.mobile.pose), 1e-12)
            << what;
        // ... that satisfies the constraints (a solved problem's branches do) ...
        if (s.status == Status::kSolved) {
          EXPECT_LT(worstViolation(p, br.nearest.pose), 1e-6) << what;
        }
        // ... and no dense sample of the branch is nearer the initial pose.
        const double dense =
            bestOverDenseSamples(m, br.nearest.parameters, p.mobile.pose, 4000, 2.0);
        EXPECT_LE(br.nearest.distance, dense + 1e-6 * (1 + dense)) << what;
        // The samples: as many as asked, on the branch.
        ASSERT_EQ(br.sample_count, static_cast<std::size_t>(options.samples)) << what;
        for (std::size_t k = 0; k < br.sample_count; ++k) {
          const SamplePose& t = r.samplesOf(b)[k];
          EXPECT_TRUE(m.pose(t.parameters).isApprox(t.pose, 1e-12)) << what;
          if (s.status == Status::kSolved) {
            EXPECT_LT(worstViolation(p, t.pose), 1e-6) << what;
          }
        }
        best = std::min(best, br.nearest.distance);
      }
      if (r.branches.empty()) {
        EXPECT_EQ(r.best, -1) << spec.file;
      } else {
        ASSERT_GE(r.best, 0) << spec.file;
        EXPECT_EQ(r.branches[static_cast<std::size_t>(r.best)].nearest.distance, best);
      }
      EXPECT_FALSE(r.collision_checked);
    }
  EXPECT_GT(branches, 40);
}

// The message echoes the user's ids of conflicting constraints; the lists are the solution's.
TEST(Evaluate, CopiesTheSolutionsListsAndNamesConflictingIds) {
  Problem p = specsIn("examples").front().problem;
  Solution s = solve(p, builtinRegistry());
  s.status = Status::kInconsistent;
  s.message = "inconsistent";
  s.conflicts = {0};
  p.constraints[0].id = "first";
  const Report r = evaluate(p, s, ReportOptions());
  EXPECT_EQ(r.message, "inconsistent (constraints 0 = 'first')");
  EXPECT_EQ(r.conflicts, s.conflicts);
  EXPECT_EQ(r.redundant, s.redundant);
  EXPECT_EQ(r.rules, s.rules);
}

// A Report reused for a smaller problem holds nothing of the larger one.
TEST(Evaluate, AReusedReportHoldsOnlyTheLastProblem) {
  std::vector<Spec> specs = specsIn("examples");
  std::sort(specs.begin(), specs.end(), [](const Spec& a, const Spec& b) {
    return solve(a.problem, builtinRegistry()).branches.size() >
           solve(b.problem, builtinRegistry()).branches.size();
  });
  ReportOptions options;
  options.samples = 4;
  const Solution big = solve(specs.front().problem, builtinRegistry());
  const Solution small = solve(specs.back().problem, builtinRegistry());
  ASSERT_GT(big.branches.size(), small.branches.size());
  Report reused;
  evaluate(specs.front().problem, big, options, reused);
  evaluate(specs.back().problem, small, options, reused);
  const Report fresh = evaluate(specs.back().problem, small, options);
  ASSERT_EQ(reused.branches.size(), fresh.branches.size());
  EXPECT_EQ(reused.samples.size(), fresh.samples.size());
  EXPECT_EQ(reused.name, fresh.name);
  EXPECT_EQ(reused.best, fresh.best);
  for (std::size_t b = 0; b < fresh.branches.size(); ++b) {
    EXPECT_EQ(reused.branches[b].nearest.parameters, fresh.branches[b].nearest.parameters);
    EXPECT_EQ(reused.branches[b].manifold, fresh.branches[b].manifold);
  }
}

// Against a scene: one verdict per branch; a free nearest pose really is free, a colliding one
// has contacts; collision_free_branches counts the branches with a free pose.
TEST(Evaluate, CollisionVerdictsAgreeWithTheScene) {
  int checked = 0;
  for (const Spec& spec : specsIn("collision")) {
    const Problem& p = spec.problem;
    const Solution s = solve(p, builtinRegistry());
    collision::MeshCache cache;
    std::vector<Diagnostic> errors, warnings;
    const auto scene = collision::buildScene(p, fs::path(spec.file).parent_path().string(), cache,
                                             &errors, &warnings);
    ASSERT_TRUE(scene) << spec.file;
    ReportOptions options;
    options.clearance = 0.001;
    options.collision_samples = 16;
    const Report r = evaluate(p, s, options, scene.get());
    ASSERT_TRUE(r.collision_checked);
    ASSERT_EQ(r.collision.size(), s.branches.size()) << spec.file;
    EXPECT_EQ(r.checked_against, scene->checkedAgainst());
    int free = 0;
    for (std::size_t b = 0; b < r.collision.size(); ++b, ++checked) {
      const CollisionReport& c = r.collision[b];
      EXPECT_EQ(c.nearest_collides, scene->collides(r.branches[b].nearest.pose, 0.001));
      EXPECT_EQ(c.nearest_collides, !c.nearest_contacts.empty());
      if (c.has_nearest_free) {
        EXPECT_FALSE(scene->collides(c.nearest_free.pose, 0.001)) << spec.file;
      } else {
        EXPECT_FALSE(c.nearest_free_reason.empty());
      }
      for (const SamplePose& t : c.free_samples) EXPECT_FALSE(scene->collides(t.pose, 0.001));
      const int dof = s.branches[b].manifold->dof();
      EXPECT_EQ(static_cast<int>(c.free_samples.size()) + c.blocked_samples, dof == 0 ? 1 : 16);
      free += c.has_nearest_free || !c.free_samples.empty();
    }
    EXPECT_EQ(r.collision_free_branches, free) << spec.file;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace relpos::test
