// Manifold::rebase (the solver centres the geometry, matches, then moves the branches back): a
// rebased copy of every built-in branch holds exactly the poses T(o_W)·pose(θ)·T(−o_M), and
// nothing else — each such pose projects onto the copy, and each pose of the copy, moved back,
// projects onto the original.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "problem_transforms.hpp"
#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

// Parameters within the bounds (unbounded lengths within ±2 of 0).
Params drawParameters(const Manifold& m, std::mt19937_64& rng) {
  Params t{};
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    const double lo = std::isfinite(p.min) ? p.min : -2.0, hi = std::isfinite(p.max) ? p.max : 2.0;
    t[i] = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return t;
}

// How far Y is from its projection onto m: translation plus rotation angle, the translation
// relative to the pose's own magnitude (a pose 1e3 away carries 1e-13 of rounding).
double offManifold(const Manifold& m, const Isometry3d& Y) {
  const Isometry3d Z = m.pose(m.project(Y));
  return (Z.translation() - Y.translation()).norm() / (1.0 + Y.translation().norm()) +
         rotationDistance(Z.linear(), Y.linear());
}

void expectRebasedSameSet(const Branch& b, std::uint64_t seed, const std::string& label) {
  const Vector3d o_W(310.0, -720.0, 205.0), o_M(-180.0, 95.0, 440.0);
  ManifoldHolder moved = b.manifold;
  ASSERT_TRUE(moved.get()->rebase(o_W, o_M)) << label << ": a built-in manifold rebases";
  const Manifold& m = *b.manifold;
  ASSERT_EQ(moved->dof(), m.dof()) << label;
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 8; ++k) {
    const Isometry3d Y = translation(o_W) * m.pose(drawParameters(m, rng)) * translation(-o_M);
    EXPECT_LT(offManifold(*moved, Y), 1e-9) << label << ": a moved pose is on the rebased copy";
    const Isometry3d Z =
        translation(-o_W) * moved->pose(drawParameters(*moved, rng)) * translation(o_M);
    EXPECT_LT(offManifold(m, Z), 1e-9) << label << ": a pose of the copy, moved back, is on it";
  }
}

TEST(ManifoldRebase, EveryBundledBranch) {
  int n = 0;
  for (const char* dir :
       {RELPOS_DATA_DIR "/examples", RELPOS_DATA_DIR "/scenarios", RELPOS_DATA_DIR "/rules"})
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      ASSERT_TRUE(r.problem) << e.path();
      const Solution s = solve(*r.problem, builtinRegistry());
      for (const Branch& b : s.branches) expectRebasedSameSet(b, ++n, e.path().stem().string());
    }
  EXPECT_GT(n, 40);
}

TEST(ManifoldRebase, RandomSingleConstraints) {
  Rng rng(91);
  int n = 0;
  for (int trial = 0; trial < 20; ++trial)
    for (const SingleKind& kind : singleKinds()) {
      KnownProblem kp = emptyKnownProblem(rng);
      addConstraint(kp, kind, rng);
      const Solution s = solve(kp.problem, builtinRegistry());
      for (const Branch& b : s.branches) expectRebasedSameSet(b, ++n, kind.label);
    }
  EXPECT_GT(n, 200);
}

}  // namespace
}  // namespace relpos::test
