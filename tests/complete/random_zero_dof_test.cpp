// Random 0-DOF problems built around a known pose (issue 15): six scalar constraints mixing
// point-point, point-line and point-plane distances and line-line / line-plane angles over 2-4
// mobile points and lines, with fixed features placed so that every constraint holds at X*. Each
// is kept only when its Jacobian at X* has full rank (X* isolated). relpos::solve must find X*
// from an unrelated initial pose, return only verified and distinct poses, and never claim the
// list complete while the random-start Newton reference finds a pose it does not hold.
#include <gtest/gtest.h>

#include <sstream>

#include "completeness_fields.hpp"
#include "evaluator.hpp"
#include "interval_check.hpp"
#include "random_problems.hpp"
#include "reference_comparison.hpp"
#include "reference_roots.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/core/solver.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

constexpr int kShards = 8;
constexpr int kPerShard = 64;  // 512 problems in all
constexpr double kPi = 3.14159265358979323846;

// One random constraint on mobile feature `name` (a point or a line at X*), its fixed feature
// new and placed to fit, its value read off at X*; values kept away from the singular ones (a
// zero distance, an angle of 0 or π) where a residual is not smooth.
void addRandomConstraint(Problem& p, const Isometry3d& X, const std::string& name,
                         const Feature& mobile, Rng& rng, int index) {
  const std::string fixed = "F" + std::to_string(index);
  const Feature w = mobile.placed(X);
  if (mobile.kind == FeatureKind::kPoint) {
    for (;;) {
      const int kind = rng.integer(0, 2);
      Feature f;
      double v;
      if (kind == 0) {
        f = Feature::makePoint(rng.point(3.0));
        v = (w.point - f.point).norm();
      } else if (kind == 1) {
        f = Feature::makeLine(rng.point(3.0), rng.unit());
        v = (w.point - f.point).cross(f.direction).norm();
      } else {
        f = Feature::makePlane(rng.point(3.0), rng.unit());
        v = (w.point - f.point).dot(f.direction);
      }
      if (kind != 2 && v < 0.3) continue;
      p.addFixedFeature(fixed, f);
      p.addConstraint("distance", fixed, name, v);
      return;
    }
  }
  for (;;) {
    const int kind = rng.integer(0, 2);
    Feature f;
    double v;
    if (kind == 0) {  // angle line-line, arccos(d̂₁·d̂₂)
      f = Feature::makeLine(rng.point(3.0), rng.unit());
      v = std::acos(std::clamp(f.direction.dot(w.direction), -1.0, 1.0));
      if (v < 0.2 || v > kPi - 0.2) continue;
      p.addFixedFeature(fixed, f);
      p.addConstraint("angle", fixed, name, v);
    } else if (kind == 1) {  // angle plane-line, arcsin(d̂·n̂)
      f = Feature::makePlane(rng.point(3.0), rng.unit());
      v = std::asin(std::clamp(f.direction.dot(w.direction), -1.0, 1.0));
      if (std::abs(v) > kPi / 2 - 0.2) continue;
      p.addFixedFeature(fixed, f);
      p.addConstraint("angle", fixed, name, v);
    } else {  // distance point(fixed)-line(mobile)
      f = Feature::makePoint(rng.point(3.0));
      v = (f.point - w.point).cross(w.direction).norm();
      if (v < 0.3) continue;
      p.addFixedFeature(fixed, f);
      p.addConstraint("distance", fixed, name, v);
    }
    return;
  }
}

struct ZeroDofProblem {
  Problem problem;
  Isometry3d X_star;
  std::string label;
};

// Problem `index`: 2-4 mobile features (at least one point), six constraints, every feature
// used; redrawn until X* is isolated with a well-conditioned Jacobian.
ZeroDofProblem makeProblem(int index) {
  Rng rng(0x5eed0000u + static_cast<std::uint64_t>(index));
  for (;;) {
    ZeroDofProblem z;
    Problem& p = z.problem;
    p.name = "random-zero-dof-" + std::to_string(index);
    z.X_star = rng.pose();
    const int features = rng.integer(2, 4);
    std::vector<std::string> names;
    std::vector<Feature> mobile;
    std::ostringstream label;
    for (int k = 0; k < features; ++k) {
      const bool point = k == 0 || rng.integer(0, 1) == 0;
      const Feature f = point ? Feature::makePoint(rng.point(1.0))
                              : Feature::makeLine(rng.point(1.0), rng.unit());
      names.push_back(std::string(point ? "p" : "l") + std::to_string(k));
      mobile.push_back(f);
      p.addMobileFeature(names.back(), f);
      label << names.back();
    }
    for (int c = 0; c < 6; ++c) {
      const int k = c < features ? c : rng.integer(0, features - 1);
      addRandomConstraint(p, z.X_star, names[k], mobile[k], rng, c);
    }
    // The initial pose: unrelated to X*.
    p.mobile.pose = rng.pose();
    int rank = 0;
    if (jacobianConditioning(p, z.X_star, &rank) < 1e-4 || rank < 6) continue;
    if (worstViolation(p, z.X_star) > 1e-12) continue;
    z.label = p.name + " (" + label.str() + ")";
    return z;
  }
}

class RandomZeroDof : public ::testing::TestWithParam<int> {};

TEST_P(RandomZeroDof, KnownPoseFoundEveryPoseVerifiedCompleteNeverWrong) {
  int failures = 0, unsolved = 0, claimed_complete = 0, complete_but_failed = 0;
  std::ostringstream report;
  auto fail = [&](const ZeroDofProblem& z, const std::string& what) {
    if (++failures <= 8) report << "\n  " << z.label << ": " << what;
  };
  for (int i = 0; i < kPerShard; ++i) {
    const ZeroDofProblem z = makeProblem(GetParam() * kPerShard + i);
    const Problem& p = z.problem;
    const Solution s = solve(p, builtinRegistry());
    if (s.status != Status::kSolved) {
      ++unsolved;
      fail(z, std::string("status ") + toString(s.status) + ": " + s.message);
      continue;
    }
    const int failures_before = failures;
    if (!someBranchContains(s, z.X_star, 1e-6))
      fail(z, "the known pose " + poseText(z.X_star) + " is on no branch\n" + describeBranches(s));
    std::string where;
    const double worst = worstSampledViolation(p, s, 4, 11, &where);
    if (worst > 1e-7)
      fail(z, "a branch pose violates a constraint by " + std::to_string(worst) + ": " + where);
    for (std::size_t a = 0; a < s.branches.size(); ++a) {
      if (s.branches[a].manifold->dof() != 0) {
        fail(z, "a branch of " + std::to_string(s.branches[a].manifold->dof()) +
                    " DOF at an isolated pose");
        continue;
      }
      for (std::size_t b = 0; b < a; ++b)
        if (s.branches[b].manifold->dof() == 0 &&
            poseDistance(branchPose(s.branches[a]), branchPose(s.branches[b])) <= 1e-6)
          fail(z, "branches " + std::to_string(b) + " and " + std::to_string(a) + " are one pose");
      // A certified branch's box, re-proven by the tests' own interval check.
      const std::optional<BranchProof> proof = proofOf(s.branches[a]);
      if (!proof || proof->exact) continue;
      const IntervalVerdict v = provesSolutionWithin(
          p, branchPose(s.branches[a]), certificateBox(proof->radius, proof->angle, false));
      if (!(proof->radius > 0) || !v.proven)
        fail(z, "branch " + std::to_string(a) + "'s certificate (radius " +
                    std::to_string(proof->radius) + ") is not re-proven: " + v.why);
    }
    // Complete is claimed by the field once it exists; before, a `solved` answer of the rules
    // claims it (docs/spec.md: relpos promises every pose).
    const bool complete = completeOf(s).value_or(true);
    if (!complete) continue;
    ++claimed_complete;
    ReferenceOptions o;
    o.starts = 300;  // about 20 ms a problem
    o.seed = 1000u + static_cast<std::uint64_t>(i);
    const ReferenceRoots ref = referenceRoots(p, o);
    for (const Isometry3d& X : ref.poses)
      if (!someBranchContains(s, X, 1e-6))
        fail(z, "complete claimed, but the reference found " + poseText(X) + " on no branch\n" +
                    describeBranches(s));
    if (failures > failures_before) ++complete_but_failed;
  }
  std::cout << "shard " << GetParam() << ": " << kPerShard << " problems, " << unsolved
            << " not solved, " << claimed_complete << " claimed complete (" << complete_but_failed
            << " of them failing a check)\n";
  EXPECT_EQ(failures, 0) << failures << " failures, the first:" << report.str();
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomZeroDof, ::testing::Range(0, kShards));

// The generator itself: every problem is 0-DOF at X* (full-rank Jacobian), holds there, and
// mixes the kinds the issue names.
TEST(RandomZeroDofGenerator, ProblemsAreIsolatedAndMixed) {
  int points = 0, lines = 0, angles = 0, distances = 0;
  for (int i = 0; i < 64; ++i) {
    const ZeroDofProblem z = makeProblem(i);
    EXPECT_EQ(z.problem.constraints.size(), 6u);
    EXPECT_LT(worstViolation(z.problem, z.X_star), 1e-12);
    int rank = 0;
    EXPECT_GT(jacobianConditioning(z.problem, z.X_star, &rank), 1e-4);
    EXPECT_EQ(rank, 6);
    EXPECT_GE(z.problem.mobile.features.size(), 2u);
    EXPECT_LE(z.problem.mobile.features.size(), 4u);
    for (const NamedFeature& f : z.problem.mobile.features)
      (f.feature.kind == FeatureKind::kPoint ? points : lines)++;
    for (const InputConstraint& c : z.problem.constraints)
      (c.type == "angle" ? angles : distances)++;
  }
  EXPECT_GT(points, 0);
  EXPECT_GT(lines, 0);
  EXPECT_GT(angles, 0);
  EXPECT_GT(distances, 0);
}

// The reference the completeness check leans on reaches the known pose from random starts: on
// the first problems, the 300-start reference holds X* (and more roots than X* alone on some).
TEST(RandomZeroDofGenerator, ReferenceReachesTheKnownPose) {
  int found = 0, roots = 0;
  const int n = 16;
  for (int i = 0; i < n; ++i) {
    const ZeroDofProblem z = makeProblem(i);
    ReferenceOptions o;
    o.starts = 300;
    o.seed = 1000u + static_cast<std::uint64_t>(i);
    const ReferenceRoots ref = referenceRoots(z.problem, o);
    roots += static_cast<int>(ref.poses.size());
    for (const Isometry3d& X : ref.poses)
      if (poseDistance(X, z.X_star) < 1e-6) {
        ++found;
        break;
      }
  }
  std::cout << roots << " roots over " << n << " problems, X* among them in " << found << "\n";
  EXPECT_GE(found, n - 1);  // a narrow basin may hide X* from 300 starts, not from most
  EXPECT_GT(roots, n);
}

}  // namespace
}  // namespace relpos::test
