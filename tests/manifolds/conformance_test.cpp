// The manifold conformance suite (STYLE.md §10): every manifold the solver can produce — every
// branch of every example and of random single-constraint problems — passes the same property
// checks: poses are rigid, pose(project(pose(θ))) == pose(θ), contains() holds on the manifold,
// parameters are well formed and respected, nearest is never worse than the projection.
#include <gtest/gtest.h>

#include <filesystem>

#include "random_problems.hpp"
#include "relpos/core/spec_io.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

void expectManifoldInvariants(const Manifold& m, std::uint64_t seed, const std::string& label) {
  SCOPED_TRACE(label + ": " + m.describe());
  std::mt19937_64 rng(seed);
  ASSERT_GE(m.dof(), 0);
  ASSERT_LE(m.dof(), kMaxDof);
  if (m.rotationalDof() >= 0) {
    EXPECT_EQ(m.rotationalDof() + m.translationalDof(), m.dof());
  }
  for (int i = 0; i < m.dof(); ++i) {
    Parameter p = m.parameter(i);
    EXPECT_NE(std::string(p.name), "");
    EXPECT_LE(p.min, p.max);
    if (p.periodic) {
      EXPECT_EQ(p.kind, ParamKind::kAngle);
    }
  }
  const Tolerance tol = Tolerance::forScale(10.0);
  for (int k = 0; k < 40; ++k) {
    Params t = sampleParams(m, rng);
    Isometry3d X = m.pose(t);
    const Matrix3d R = X.linear();
    ASSERT_LT((R.transpose() * R - Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    ASSERT_NEAR(R.determinant(), 1.0, 1e-12);
    Params back = m.project(X);
    for (int i = 0; i < m.dof(); ++i) {
      Parameter p = m.parameter(i);
      if (!p.periodic) {
        EXPECT_GE(back[i], p.min - 1e-9) << p.name;
        EXPECT_LE(back[i], p.max + 1e-9) << p.name;
      }
    }
    EXPECT_LT(poseDistance(m.pose(back), X), 1e-7)
        << "project does not return a pose on the manifold: " << poseText(X);
    EXPECT_TRUE(m.contains(X, tol)) << poseText(X);
    // Off the manifold: nearest is never worse than the projection, and stays in bounds.
    Isometry3d Y = X;
    Y.translation() += Vector3d(0.3, -0.2, 0.4);
    Y.linear() = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()) * Y.linear();
    Params n = nearestParams(m, Y);
    EXPECT_LE(poseDistance(m.pose(n), Y), poseDistance(m.pose(m.project(Y)), Y) + 1e-12);
  }
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
