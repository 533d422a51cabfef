// Random 0-DOF problems built around a known pose (issue 15): six scalar constraints mixing
// point-point, point-line and point-plane distances and line-line / line-plane angles over 2-4
// mobile points and lines, with fixed features placed so that every constraint holds at X*. Each
// is kept only when its Jacobian at X* has full rank (X* isolated). relpos::solve must find X*
// from an unrelated initial pose, return only verified and distinct poses, and never claim the
// list complete while the random-start Newton reference finds a pose it does not hold.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "completeness_fields.hpp"
#include "evaluator.hpp"
#include "interval_check.hpp"
#include "random_problems.hpp"
#include "reference_comparison.hpp"
#include "reference_roots.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/core/solver.hpp"
#include "slow_tests.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

constexpr int kShards = 8;
constexpr int kPerShard = 66;           // 528 problems in all
constexpr int kStructuresPerShard = 3;  // 24 structures, each with 22 random geometries
constexpr double kPi = 3.14159265358979323846;

// The structure of a problem: its mobile features (points and lines) and, per constraint, the
// feature it holds and its kind (0-2, read per feature kind by addRandomConstraint). The
// numeric stage computes a start system once per structure (a constraint signature) and keeps
// it for the process, so the problems are drawn as random geometries over a pool of random
// structures: 24 signatures, 22 problems each, instead of 528 signatures (each a monodromy run
// of ~1 s or more). RandomZeroDofFresh draws a new structure for every problem (by hand only).
struct Structure {
  std::vector<bool> is_point;
  std::vector<int> feature;  // per constraint
  std::vector<int> kind;     // per constraint
};

Structure randomStructure(Rng& rng) {
  Structure st;
  const int features = rng.integer(2, 4);
  for (int k = 0; k < features; ++k) st.is_point.push_back(k == 0 || rng.integer(0, 1) == 0);
  for (int c = 0; c < 6; ++c) {
    st.feature.push_back(c < features ? c : rng.integer(0, features - 1));
    st.kind.push_back(rng.integer(0, 2));
  }
  return st;
}

// One random constraint of `kind` on mobile feature `name` (a point or a line at X*), its fixed
// feature new and placed to fit, its value read off at X*; values kept away from the singular
// ones (a zero distance, an angle of 0 or π) where a residual is not smooth.
void addRandomConstraint(Problem& p, const Isometry3d& X, const std::string& name,
                         const Feature& mobile, int kind, Rng& rng, int index) {
  const std::string fixed = "F" + std::to_string(index);
  const Feature w = mobile.placed(X);
  if (mobile.kind == FeatureKind::kPoint) {
    for (;;) {
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

// A problem of structure `st` (2-4 mobile features, at least one point, six constraints, every
// feature used), its geometry from `seed`; redrawn until X* is isolated with a well-conditioned
// Jacobian.
// Some structures can never be isolated (every constraint on the rotation, say): after `tries`
// draws the problem is returned without a label, and the pool draws another structure.
ZeroDofProblem makeProblemOf(const Structure& st, std::uint64_t seed, const std::string& name,
                             int tries = 1000000) {
  Rng rng(seed);
  for (int attempt = 0; attempt < tries; ++attempt) {
    ZeroDofProblem z;
    Problem& p = z.problem;
    p.name = name;
    z.X_star = rng.pose();
    std::vector<std::string> names;
    std::vector<Feature> mobile;
    std::ostringstream label;
    for (std::size_t k = 0; k < st.is_point.size(); ++k) {
      const bool point = st.is_point[k];
      const Feature f = point ? Feature::makePoint(rng.point(1.0))
                              : Feature::makeLine(rng.point(1.0), rng.unit());
      names.push_back(std::string(point ? "p" : "l") + std::to_string(k));
      mobile.push_back(f);
      p.addMobileFeature(names.back(), f);
      label << names.back();
    }
    for (int c = 0; c < 6; ++c) {
      const int k = st.feature[static_cast<std::size_t>(c)];
      addRandomConstraint(p, z.X_star, names[static_cast<std::size_t>(k)],
                          mobile[static_cast<std::size_t>(k)], st.kind[static_cast<std::size_t>(c)],
                          rng, c);
      label << (c ? "," : ":") << k << "/" << st.kind[static_cast<std::size_t>(c)];
    }
    // The initial pose: unrelated to X*.
    p.mobile.pose = rng.pose();
    int rank = 0;
    if (jacobianConditioning(p, z.X_star, &rank) < 1e-4 || rank < 6) continue;
    if (worstViolation(p, z.X_star) > 1e-12) continue;
    z.label = p.name + " (" + label.str() + ")";
    return z;
  }
  return ZeroDofProblem{};
}

// Structure s of the pool (s = 0 … kShards · kStructuresPerShard − 1).
Structure poolStructure(int s) {
  Rng rng(0x57c0000u + static_cast<std::uint64_t>(s));
  for (;;) {
    Structure st = randomStructure(rng);
    if (!makeProblemOf(st, 1, "probe", 200).label.empty()) return st;
  }
}

// Problem `index`: shard index / kPerShard draws over its own structures of the pool.
ZeroDofProblem makeProblem(int index) {
  const int shard = index / kPerShard;
  const int structure = shard * kStructuresPerShard + index % kStructuresPerShard;
  return makeProblemOf(poolStructure(structure), 0x5eed0000u + static_cast<std::uint64_t>(index),
                       "random-zero-dof-" + std::to_string(index));
}

// Problem `index` of a fresh structure (its own signature).
ZeroDofProblem makeFreshProblem(int index) {
  Rng rng(0xf7e5000u + static_cast<std::uint64_t>(index));
  Structure st = randomStructure(rng);
  while (makeProblemOf(st, 1, "probe", 200).label.empty()) st = randomStructure(rng);
  return makeProblemOf(st, 0xf7e5800u + static_cast<std::uint64_t>(index),
                       "random-zero-dof-fresh-" + std::to_string(index));
}

class RandomZeroDof : public ::testing::TestWithParam<int> {};

// Checks problems make(first) … make(first + count − 1); label names them in the report.
void checkProblems(ZeroDofProblem (*make)(int), int first, int count, const std::string& label) {
  int failures = 0, unsolved = 0, claimed_complete = 0, complete_but_failed = 0, missed = 0;
  std::ostringstream missed_report;
  std::ostringstream report;
  auto fail = [&](const ZeroDofProblem& z, const std::string& what) {
    if (++failures <= 8) report << "\n  " << z.label << ": " << what;
  };
  for (int i = 0; i < count; ++i) {
    const ZeroDofProblem z = make(first + i);
    const Problem& p = z.problem;
    const auto t0 = std::chrono::steady_clock::now();
    const Solution s = solve(p, builtinRegistry());
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (ms > 1000.0 || std::getenv("RELPOS_TEST_TIMES"))
      std::cout << z.label << ": " << toString(s.status) << " in " << ms << " ms\n" << std::flush;
    if (s.status != Status::kSolved) {
      ++unsolved;
      fail(z, std::string("status ") + toString(s.status) + ": " + s.message);
      continue;
    }
    const int failures_before = failures;
    // X* is isolated (full-rank Jacobian): missing it while claiming every isolated pose found
    // is a wrong claim; missing it without the claim is a shortfall, counted and bounded below.
    if (!someBranchContains(s, z.X_star, 1e-6)) {
      if (s.isolated_complete || s.complete)
        fail(z, "the known pose " + poseText(z.X_star) +
                    " is on no branch, but every isolated pose was claimed found\n" +
                    describeBranches(s));
      else if (++missed <= 4)
        missed_report << "\n  " << z.label << ": the known pose is on no branch (not claimed)";
    }
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
    const bool complete = completeOf(s).value_or(true) || s.isolated_complete;
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
  std::cout << label << ": " << count << " problems, " << unsolved << " not solved, "
            << claimed_complete << " claimed complete (" << complete_but_failed
            << " of them failing a check)\n";
  EXPECT_EQ(failures, 0) << failures << " failures, the first:" << report.str();
  std::cout << label << ": the known pose missed in " << missed << " (never claimed complete)"
            << missed_report.str() << "\n";
  // The target is 0 (issue 15); measured at landing: 1 of 66 in shard 0. A start system computed
  // in the process can undercount the family's roots (docs/spec.md §8.5).
  EXPECT_LE(missed, count / 16) << missed_report.str();
}

TEST_P(RandomZeroDof, KnownPoseFoundEveryPoseVerifiedCompleteNeverWrong) {
  // Some structures' start systems take minutes to compute (docs/spec.md §8.5; shard 1's ran
  // over 7 minutes in CI): by default shards 0 and 2 (132 problems, about 30 s each in Release),
  // all 528 with RELPOS_SLOW_TESTS=1; under a sanitizer (CI's second run) shard 0 only.
  const bool by_default = GetParam() == 0 || (GetParam() == 2 && !kSanitizedBuild);
  if (!by_default && !slowTestsWanted()) GTEST_SKIP() << "set RELPOS_SLOW_TESTS=1 to run";
  checkProblems(&makeProblem, GetParam() * kPerShard, kPerShard,
                "shard " + std::to_string(GetParam()));
}

// Every problem its own structure: a start system computed per problem.
TEST(RandomZeroDofFresh, KnownPoseFoundEveryPoseVerifiedCompleteNeverWrong) {
  // A start system per problem: 0.1 s to minutes each (docs/spec.md §8.5), so by hand only.
  if (!slowTestsWanted()) GTEST_SKIP() << "set RELPOS_SLOW_TESTS=1 to run";
  checkProblems(&makeFreshProblem, 0, 12, "fresh structures");
}

INSTANTIATE_TEST_SUITE_P(Shards, RandomZeroDof, ::testing::Range(0, kShards));

// The generator itself: every problem is 0-DOF at X* (full-rank Jacobian), holds there, and
// mixes the kinds the issue names.
TEST(RandomZeroDofGenerator, ProblemsAreIsolatedAndMixed) {
  int points = 0, lines = 0, angles = 0, distances = 0;
  // Two problems of every structure of the pool (problem index → structure: makeProblem).
  for (int i = 0; i < 2 * kShards * kStructuresPerShard; ++i) {
    const int structure = i % (kShards * kStructuresPerShard);
    const int shard = structure / kStructuresPerShard;
    const ZeroDofProblem z =
        makeProblem(shard * kPerShard + structure % kStructuresPerShard +
                    kStructuresPerShard * (i / (kShards * kStructuresPerShard)));
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
