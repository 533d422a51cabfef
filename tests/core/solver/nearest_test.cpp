// The nearest pose of a branch (docs/spec.md §2 `nearest`) on the bundled generated grasp and weld
// specs, which cover every manifold the batch produces (separable with and without closed-form
// translations, both radial grasps): no sampled pose of the branch is nearer, and the parameters
// set in closed form during the search (Manifold::closedFormParams) are the nearest given the
// others. The same again with every mobile point moved off the tool's axis, where the spin about
// that axis moves the translation and must be searched, not set in closed form.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

std::vector<Problem> generatedProblems() {
  std::vector<Problem> v;
  std::ifstream in(RELPOS_DATA_DIR "/batch/grasp-and-weld-100.jsonl");
  for (std::string line; std::getline(in, line);) {
    ParseResult r = parseSpec(line, builtinRegistry());
    if (r.problem) v.push_back(*r.problem);
  }
  return v;
}

// The mobile object's origin 11 mm and 6 mm off its tool axis (the generated tools' z axis): every
// mobile feature moved by the same offset, so the problems keep their solutions' shape.
std::vector<Problem> offAxisProblems() {
  std::vector<Problem> v = generatedProblems();
  for (Problem& p : v)
    for (InputConstraint& c : p.constraints) c.mobile.point += Vector3d(0.011, -0.006, 0.0);
  return v;
}

int closedCount(unsigned bits) {
  int n = 0;
  for (; bits != 0u; bits &= bits - 1u) ++n;
  return n;
}

TEST(Nearest, OffAxisPointsLeaveTheSpinToTheSearch) {
  const std::vector<Problem> on = generatedProblems(), off = offAxisProblems();
  int fewer = 0;
  for (std::size_t k = 0; k < on.size(); ++k) {
    const Solution a = solve(on[k], builtinRegistry()), b = solve(off[k], builtinRegistry());
    ASSERT_EQ(a.branches.size(), b.branches.size()) << on[k].name;
    for (std::size_t i = 0; i < a.branches.size(); ++i) {
      const int n_on = closedCount(a.branches[i].manifold->closedFormParams());
      const int n_off = closedCount(b.branches[i].manifold->closedFormParams());
      EXPECT_LE(n_off, n_on) << on[k].name;
      fewer += n_off < n_on;
    }
  }
  // Every weld, cylinder and cup branch loses its spin; the trays have none.
  EXPECT_GT(fewer, 90);
}

class NearestOn : public ::testing::TestWithParam<bool> {
 protected:
  std::vector<Problem> problems() const {
    return GetParam() ? offAxisProblems() : generatedProblems();
  }
};
INSTANTIATE_TEST_SUITE_P(Tips, NearestOn, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "OffAxis" : "OnAxis"; });

TEST_P(NearestOn, NoSampledPoseOfABranchIsNearer) {
  std::mt19937_64 rng(71);
  int branches = 0, with_closed_form = 0;
  for (const Problem& p : problems()) {
    const Solution s = solve(p, builtinRegistry());
    for (const Branch& b : s.branches) {
      const NearestPose n = nearestOnBranch(b, p.mobile.pose);
      ++branches;
      with_closed_form += b.manifold->closedFormParams() != 0u;
      for (int k = 0; k < 400; ++k) {
        const Params t = sampleParameters(*b.manifold, n.parameters, 0.05, rng);
        ASSERT_GE(poseDistance(b.manifold->pose(t), p.mobile.pose), n.distance - 1e-9)
            << p.name << " branch " << b.manifold->describe();
      }
    }
  }
  EXPECT_GT(branches, 100);
  EXPECT_GT(with_closed_form, 50);
}

TEST_P(NearestOn, ClosedFormParametersAreTheNearestGivenTheOthers) {
  std::mt19937_64 rng(72);
  int checked = 0;
  for (const Problem& p : problems()) {
    const Solution s = solve(p, builtinRegistry());
    for (const Branch& b : s.branches) {
      const Manifold& m = *b.manifold;
      const unsigned closed = m.closedFormParams();
      if (closed == 0u) continue;
      for (int k = 0; k < 20; ++k) {
        Params t = sampleParameters(m, m.project(p.mobile.pose), 0.2, rng);
        const Isometry3d Y = m.poseWithTail(p.mobile.pose, &t);
        const double d = poseDistance(Y, p.mobile.pose);
        // The pose it returns is the branch's pose at the parameters it filled in.
        ASSERT_LT(poseDistance(Y, m.pose(t)), 1e-12) << p.name << " " << m.describe();
        // Moving any closed-form parameter (within its bounds) never brings the pose nearer.
        for (int i = 0; i < m.dof(); ++i) {
          if (!(closed & (1u << i))) continue;
          const Parameter par = m.parameter(i);
          for (double step : {-1e-2, -1e-4, 1e-4, 1e-2}) {
            Params u = t;
            u[i] = std::min(par.max, std::max(par.min, u[i] + step));
            EXPECT_GE(poseDistance(m.pose(u), p.mobile.pose), d - 1e-12)
                << p.name << " " << m.describe() << " parameter " << par.name;
          }
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace relpos::test
