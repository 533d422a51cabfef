// Branches as TSR chains (relpos/report/tsr.hpp, issue 17), checked with the tests' evaluator
// (written from docs/spec.md §1 alone): every pose drawn from an exported chain's bounds satisfies
// every input constraint, and the chain at b = 0 is the branch's nearest pose.
#include "relpos/report/tsr.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "evaluator.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

struct Exported {
  int branches = 0, chains = 0;
};

// Exports every branch of the spec, checks each chain, and counts.
Exported checkSpec(const std::string& file, double window = 0.5) {
  Exported n;
  ParseResult r = parseSpecFile(file, builtinRegistry());
  if (!r.problem) return n;
  const Problem& p = *r.problem;
  const Solution s = solve(p, builtinRegistry());
  const double size = std::max(1.0, p.lengthScale());
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Branch& b : s.branches) {
    ++n.branches;
    const NearestPose near = nearestOnBranch(b, p.mobile.pose);
    const TsrExport e = tsrChainOf(p, b, near.parameters, window);
    if (!e.exact) {
      EXPECT_FALSE(e.why.empty()) << file;
      EXPECT_TRUE(e.chain.empty()) << file;
      continue;
    }
    ++n.chains;
    // as personalrobotics/tsr composes a chain: later links start at the pose so far
    for (std::size_t l = 1; l < e.chain.size(); ++l)
      EXPECT_TRUE(e.chain[l].T0_w.isApprox(Isometry3d::Identity(), 0.0)) << file;
    // b = 0 in every link: the nearest pose the chain was built about
    const std::vector<std::array<double, 6>> zero(e.chain.size(), std::array<double, 6>{});
    const Isometry3d X0 = tsrChainPose(e.chain, zero);
    EXPECT_LT((X0.translation() - near.pose.translation()).norm(), 1e-9 * size) << file;
    EXPECT_LT(rotationDistance(X0.linear(), near.pose.linear()), 1e-9) << file;
    for (int k = 0; k < 100; ++k) {
      std::vector<std::array<double, 6>> draw(e.chain.size());
      for (std::size_t l = 0; l < e.chain.size(); ++l)
        for (std::size_t row = 0; row < 6; ++row) {
          const auto& bw = e.chain[l].Bw[row];
          EXPECT_LE(bw[0], bw[1]) << file;
          draw[l][row] = bw[0] + (bw[1] - bw[0]) * u(rng);
        }
      int which = -1;
      const double v = worstViolation(p, tsrChainPose(e.chain, draw), &which);
      EXPECT_LE(v, 1e-9 * size) << file << ": a pose drawn from the chain breaks constraint "
                                << which << " by " << v << " (" << b.manifold->describe() << ")";
    }
  }
  return n;
}

TEST(TsrChain, EveryPoseDrawnFromAnExportedChainSatisfiesTheSpec) {
  Exported all;
  for (const char* folder : {"examples", "scenarios", "rules"})
    for (const auto& e : fs::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder)) {
      if (e.path().extension() != ".json") continue;
      const Exported n = checkSpec(e.path().string());
      all.branches += n.branches;
      all.chains += n.chains;
    }
  // Most closed-form branches are a turn or a slide per parameter.
  EXPECT_GT(all.chains, all.branches / 2) << all.chains << " chains of " << all.branches;
  std::printf("%d chains of %d branches\n", all.chains, all.branches);
}

// A narrow range (0.2 mm of a distance, 1° of an angle) is a bound like any other.
TEST(TsrChain, NarrowRangesExport) {
  Problem p;
  p.addFixedFeature("floor", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("post", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("tip", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("axis", Feature::makeLine({0, 0, 0}, {0, 0, 1}));
  p.addConstraint(ConstraintSpec("coincident", "post", "tip"))
      .addConstraint(ConstraintSpec("distance", "floor", "tip").range(0.0300, 0.0302))
      .addConstraint(ConstraintSpec("angle", "post", "axis").range(0.5, 0.5 + kPi / 180));
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  for (const Branch& b : s.branches) {
    const NearestPose near = nearestOnBranch(b, p.mobile.pose);
    const TsrExport e = tsrChainOf(p, b, near.parameters, 0.5);
    EXPECT_TRUE(e.exact) << b.manifold->describe() << ": " << e.why;
  }
}

TEST(TsrChain, SomanisScenariosExport) {
  // A (plane distance), B (seam welding), C (cylinder grasp: the fingers' point turns around the
  // cylinder, which the orientation turns freely about), D (soda-can grasp), E (tray grasp):
  // every branch.
  for (const char* name : {"scenario-a-plane-distance", "scenario-b-seam-welding",
                           "scenario-c-cylinder-grasp", "scenario-d-soda-can-grasp",
                           "scenario-e-tray-grasp"}) {
    const Exported n = checkSpec(std::string(RELPOS_DATA_DIR) + "/scenarios/" + name + ".json");
    EXPECT_GT(n.branches, 0) << name;
    EXPECT_EQ(n.chains, n.branches) << name;
  }
}

TEST(TsrChain, ASpinAndASlideAreOneTsrAboutTheAxis) {
  // A peg in a hole along z through (1, 2, 0): one link, frame on the axis, z and yaw free.
  Problem p;
  p.addFixedFeature("hole", Feature::makeLine({1, 2, 0}, {0, 0, 1}))
      .addMobileFeature("peg", Feature::makeLine({0, 0, 0}, {0, 0, 1}));
  p.addConstraint("coincident", "hole", "peg");
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.branches.size(), 1u);
  const NearestPose near = nearestOnBranch(s.branches[0], p.mobile.pose);
  const TsrExport e = tsrChainOf(p, s.branches[0], near.parameters, 0.25);
  ASSERT_TRUE(e.exact) << e.why;
  ASSERT_EQ(e.chain.size(), 1u);
  const TsrLink& l = e.chain[0];
  EXPECT_NEAR(std::abs(l.T0_w.linear().col(2).z()), 1.0, 1e-12);
  EXPECT_NEAR(l.T0_w.translation().x(), 1.0, 1e-12);
  EXPECT_NEAR(l.T0_w.translation().y(), 2.0, 1e-12);
  EXPECT_TRUE(e.windowed);  // the slide is unbounded: ±0.25 about the nearest pose
  EXPECT_NEAR(l.Bw[2][1] - l.Bw[2][0], 0.5, 1e-12);
  EXPECT_NEAR(l.Bw[5][1] - l.Bw[5][0], 2 * kPi, 1e-12);
  for (std::size_t row : {0u, 1u, 3u, 4u}) EXPECT_EQ(l.Bw[row][0], l.Bw[row][1]);
}

}  // namespace
}  // namespace relpos::test
