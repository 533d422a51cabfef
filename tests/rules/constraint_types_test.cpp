// Decomposition (PMF Table I): a pose satisfies an input constraint exactly when it satisfies
// every fundamental constraint of one of its alternatives. Checked both ways on random problems:
// the known pose satisfies an alternative, and a pose violating the input violates every one.
#include <gtest/gtest.h>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/plugins/conformance.hpp"
#include "solve_helpers.hpp"
#include "test_fallback.hpp"

namespace relpos::test {
namespace {

bool satisfiesSomeAlternative(const Decomposition& d, const Isometry3d& X, double tol) {
  for (const auto& alt : d.alternatives) {
    bool all = true;
    for (const Fundamental& f : alt) all = all && plugins::fundamentalResidual(f, X) <= tol;
    if (all) return true;
  }
  return false;
}

Decomposition decompose(const Problem& p, const InputConstraint& c) {
  Decomposition d;
  const ConstraintType* t = builtinRegistry().constraintType(c.type);
  EXPECT_NE(t, nullptr);
  t->decompose(c, c.fixed.placed(p.fixed.pose), 1, d, t->context);
  return d;
}

TEST(Decomposition, KnownPoseSatisfiesAnAlternative) {
  Rng rng(8);
  for (const SingleKind& kind : singleKinds())
    for (int k = 0; k < 20; ++k) {
      KnownProblem kp = emptyKnownProblem(rng, k % 2);
      addConstraint(kp, kind, rng, k % 2);
      Decomposition d = decompose(kp.problem, kp.problem.constraints[0]);
      ASSERT_EQ(d.unhandled, nullptr) << kind.label;
      ASSERT_EQ(static_cast<int>(d.alternatives.size()), kind.branches) << kind.label;
      EXPECT_TRUE(satisfiesSomeAlternative(d, kp.X_WM_star, 1e-9)) << kind.label;
    }
}

TEST(Decomposition, ViolatingPosesSatisfyNoAlternative) {
  Rng rng(9);
  for (const SingleKind& kind : singleKinds())
    for (int k = 0; k < 20; ++k) {
      KnownProblem kp = emptyKnownProblem(rng);
      addConstraint(kp, kind, rng);
      Decomposition d = decompose(kp.problem, kp.problem.constraints[0]);
      Isometry3d X = rng.pose();
      const bool holds = worstViolation(kp.problem, X) <= 1e-9;
      EXPECT_EQ(satisfiesSomeAlternative(d, X, 1e-9), holds) << kind.label;
    }
}

TEST(Decomposition, MixedConstraintWithOthersIsUnhandledNotGuessed) {
  // A cylinder-line tangency alone is a mixed manifold; with a second constraint no rule or
  // manifold applies yet, and the rules say so (the registry here has no numeric stage, which
  // would answer it with charts: docs/spec.md §8.7).
  Problem p;
  p.addFixedFeature("L", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("A", Feature::makePoint({0, 0, 3}))
      .addMobileFeature("C", Feature::makeCylinder({0, 0, 0}, {0, 1, 0}, 0.5))
      .addMobileFeature("p", Feature::makePoint({0, 0, 1}));
  p.addConstraint("tangent", "L", "C");
  EXPECT_EQ(solve(p, builtinRegistry()).status, Status::kSolved);
  p.addConstraint("distance", "A", "p", 1.0);
  Solution s = solve(p, rulesOnlyRegistry());
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_NE(s.message.find("line-line"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace relpos::test

namespace relpos::test {
namespace {

TEST(Decomposition, ProblemsBuiltInCodeAreCheckedLikeSpecs) {
  Problem p;
  p.addFixedFeature("Q", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addMobileFeature("l", Feature::makeLine({0, 0, 0}, {0, 1, 0}))
      .addMobileFeature("p", Feature::makePoint({0, 0, 0}));
  p.addConstraint("angle", "Q", "l", 1.0);  // an angle needs two directions
  Solution s = solve(p, builtinRegistry());
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_NE(s.message.find("does not accept point-line"), std::string::npos) << s.message;
  Problem q;
  q.addFixedFeature("K", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addMobileFeature("p", Feature::makePoint({0, 0, 0}));
  q.addConstraint("distance", "K", "p", -2.0);
  Solution t = solve(q, builtinRegistry());
  EXPECT_EQ(t.status, Status::kUnhandled);
  EXPECT_NE(t.message.find("negative value"), std::string::npos) << t.message;
}

TEST(Decomposition, LooserToleranceAcceptsRoundedData) {
  // Two parallelisms whose angles differ by 1e-7 (six-digit CAD data): inconsistent at the
  // default 1e-9, solved with a 1e-6 angle tolerance.
  Problem p;
  p.addFixedFeature("X", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("D", Feature::makeLine({0, 0, 0}, {0.707107, 0.707107, 0}))
      .addMobileFeature("x", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addMobileFeature(
          "d", Feature::makeLine({0, 0, 0}, {0.7071067811865476, 0.7071067811865476 + 2e-7, 0}));
  p.addConstraint("parallel", "X", "x").addConstraint("parallel", "D", "d");
  EXPECT_EQ(solve(p, builtinRegistry()).status, Status::kInconsistent);
  SolverOptions loose;
  loose.angle_tolerance = 1e-6;
  EXPECT_EQ(solve(p, builtinRegistry(), loose).status, Status::kSolved);
}

}  // namespace
}  // namespace relpos::test
