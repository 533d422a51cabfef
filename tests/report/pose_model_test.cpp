// A branch's poses as the viewer's page evaluates them (relpos/report/pose_model.hpp): the screw
// product equals the branch's own pose function over its whole box, a table's nodes are the
// branch's poses, and every pose either gives satisfies the spec (the tests' evaluator, written
// from docs/spec.md alone).
#include "relpos/report/pose_model.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

struct Count {
  int branches = 0, products = 0, tables = 0;
};

// Checks the model of every branch of p, counted into n; `what` names it in failures.
void checkModels(const Problem& p, const std::string& what, Rng& rng, Count& n) {
  const Solution s = solve(p, builtinRegistry());
  const double size = std::max(1.0, p.lengthScale());
  for (const Branch& b : s.branches) {
    ++n.branches;
    const Manifold& m = *b.manifold;
    const NearestPose near = nearestOnBranch(b, p.mobile.pose);
    const PoseModel model = poseModelOf(p, b, near.parameters, 0.5, 512);
    const int dof = m.dof();
    // θ* itself: the nearest pose, whichever the model.
    const std::optional<Isometry3d> X0 = modelPose(model, dof, near.parameters);
    ASSERT_TRUE(X0.has_value()) << what;
    EXPECT_LT((X0->translation() - near.pose.translation()).norm(), 1e-9 * size) << what;
    EXPECT_LT(rotationDistance(X0->linear(), near.pose.linear()), 1e-9) << what;
    // Each parameter's range holds θ* and keeps within its bounds.
    for (int i = 0; i < dof; ++i) {
      const Parameter par = m.parameter(i);
      EXPECT_LE(model.range[i][0], near.parameters[i] + 1e-12) << what;
      EXPECT_GE(model.range[i][1], near.parameters[i] - 1e-12) << what;
      if (std::isfinite(par.min) && !par.periodic) {
        EXPECT_GE(model.range[i][0], par.min) << what;
      }
      if (std::isfinite(par.max) && !par.periodic) {
        EXPECT_LE(model.range[i][1], par.max) << what;
      }
    }
    std::vector<Params> points;
    if (model.product) {
      ++n.products;
      EXPECT_EQ(static_cast<int>(model.factors.size()), dof) << what;
      for (int k = 0; k < 40; ++k) {
        Params t = near.parameters;
        for (int i = 0; i < dof; ++i) t[i] = rng.uniform(model.range[i][0], model.range[i][1]);
        points.push_back(t);
      }
    } else {
      ++n.tables;
      std::size_t total = 1;
      for (int i = 0; i < dof; ++i) {
        ASSERT_GE(model.count[i], 1) << what;
        total *= static_cast<std::size_t>(model.count[i]);
      }
      EXPECT_EQ(model.table.size(), total) << what;
      EXPECT_LE(total, 512u) << what;
      for (int k = 0; k < 40; ++k) {  // grid nodes, θ*'s own value exactly θ*
        Params t = near.parameters;
        for (int i = 0; i < dof; ++i) {
          const double v = model.range[i][0] + model.step[i] * rng.integer(0, model.count[i] - 1);
          if (std::abs(v - near.parameters[i]) > 1e-9 * model.step[i]) t[i] = v;
        }
        points.push_back(t);
      }
    }
    for (const Params& t : points) {
      const std::optional<Isometry3d> Y = modelPose(model, dof, t);
      if (!Y) continue;  // the branch threw there
      const Isometry3d X = m.pose(t);
      EXPECT_LT((X.translation() - Y->translation()).norm(), 1e-9 * size)
          << what << ": the model is not the branch (" << m.describe() << ")";
      EXPECT_LT(rotationDistance(X.linear(), Y->linear()), 1e-9) << what;
      int which = -1;
      const double v = worstViolation(p, *Y, &which);
      EXPECT_LE(v, (b.exact ? 1e-9 : 1e-6) * size)
          << what << ": the model's pose breaks constraint " << which << " by " << v;
    }
  }
}

TEST(PoseModel, BundledBranchesAreTheirModels) {
  Count all;
  Rng rng(23);
  for (const char* folder : {"examples", "scenarios", "rules", "tasks"})
    for (const auto& e : fs::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      if (!r.problem) continue;
      checkModels(*r.problem, e.path().string(), rng, all);
    }
  EXPECT_EQ(all.products + all.tables, all.branches);
  // Most closed forms are a product of screws, rigid or separable; the rest (charts, a rotation
  // whose second angle follows the first nonlinearly, ellipses) are tables.
  EXPECT_GT(all.products, all.branches * 3 / 4) << all.products << " of " << all.branches;
  std::printf("%d products, %d tables of %d branches\n", all.products, all.tables, all.branches);
}

TEST(PoseModel, RandomProblemsAreTheirModels) {
  Rng rng(31);
  Count all;
  const auto& kinds = singleKinds();
  for (int trial = 0; trial < 300; ++trial) {
    KnownProblem kp = emptyKnownProblem(rng);
    const int constraints = rng.integer(1, 2);
    for (int c = 0; c < constraints; ++c)
      addConstraint(
          kp, kinds[static_cast<std::size_t>(rng.integer(0, static_cast<int>(kinds.size()) - 1))],
          rng);
    checkModels(kp.problem, "random problem " + std::to_string(trial), rng, all);
  }
  EXPECT_GT(all.branches, 300);
  EXPECT_GT(all.products, all.branches / 2) << all.products << " of " << all.branches;
  std::printf("%d products, %d tables of %d branches\n", all.products, all.tables, all.branches);
}

}  // namespace
}  // namespace relpos::test
