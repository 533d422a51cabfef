// The numeric stage's hook (core/src/fallback.cpp, docs/spec.md §8): Solution::complete for what
// the rules answer, the fallback called only for what they leave `unhandled`, its certified answer
// kept, and everything that can go wrong with it (a throw, a decline, a bad certificate, a pose
// that breaks a constraint) leaving the rules' `unhandled` with the reason.
#include <gtest/gtest.h>

#include <string>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/manifolds/separable.hpp"
#include "solve_helpers.hpp"
#include "test_fallback.hpp"

namespace relpos::test {
namespace {

// The mobile origin on a fixed point: solved by the rules (one 3-DOF branch of rotations).
Problem pointOnPoint() {
  Problem p;
  p.addFixedFeature("O", Feature::makePoint(Vector3d(1, 2, 3)));
  p.addMobileFeature("o", Feature::makePoint(Vector3d::Zero()));
  p.addConstraint("coincident", "O", "o");
  return p;
}

// Two mobile points 1 apart held on fixed points 5 apart: inconsistent, by the rules.
Problem pointsTooFarApart() {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint(Vector3d(0, 0, 0)));
  p.addFixedFeature("B", Feature::makePoint(Vector3d(5, 0, 0)));
  p.addMobileFeature("a", Feature::makePoint(Vector3d(0, 0, 0)));
  p.addMobileFeature("b", Feature::makePoint(Vector3d(1, 0, 0)));
  p.addConstraint("coincident", "A", "a");
  p.addConstraint("coincident", "B", "b");
  return p;
}

TEST(Complete, TrueForWhatTheRulesSolveOrProveInconsistent) {
  const Solution solved = solve(pointOnPoint(), rulesOnlyRegistry());
  ASSERT_EQ(solved.status, Status::kSolved) << solved.message;
  EXPECT_TRUE(solved.complete);
  for (const Branch& b : solved.branches) {
    EXPECT_TRUE(b.exact);
    EXPECT_EQ(b.certified.radius, 0.0);
    EXPECT_EQ(b.certified.angle, 0.0);
  }
  const Solution none = solve(pointsTooFarApart(), rulesOnlyRegistry());
  ASSERT_EQ(none.status, Status::kInconsistent) << none.message;
  EXPECT_TRUE(none.complete);
}

TEST(Complete, FalseForWhatTheRulesLeaveUnhandled) {
  const Solution s = solve(platformProblem(platformPose()), rulesOnlyRegistry());
  ASSERT_EQ(s.status, Status::kUnhandled) << describeBranches(s);
  EXPECT_FALSE(s.complete);
  EXPECT_FALSE(s.message.empty());
}

TEST(Complete, AReusedSolutionStartsIncomplete) {
  Workspace ws;
  Solution s;
  solve(pointOnPoint(), rulesOnlyRegistry(), SolverOptions(), ws, s);
  ASSERT_TRUE(s.complete);
  s.clear();
  EXPECT_FALSE(s.complete);
  solve(platformProblem(platformPose()), rulesOnlyRegistry(), SolverOptions(), ws, s);
  EXPECT_FALSE(s.complete);
}

// A plugin's matcher that marks its branch certified: only the numeric stage certifies.
MatchResult certifyingMatcher(MatchContext& ctx, const void*) {
  Branch b;
  b.manifold.emplace<manifolds::SeparableManifold>(
      manifolds::rotation::Fixed(Matrix3d::Identity()),
      manifolds::translation::Point(
          Fundamental::pointPoint(Vector3d::Zero(), Vector3d(1, 2, 3), 0.0, 1)));
  b.exact = false;
  b.certified = {1e-12, 0.0};
  return ctx.branches.add(b) ? MatchResult::kMatched : MatchResult::kOverflow;
}

TEST(Complete, APluginsMatcherCannotCertify) {
  Registry r;
  for (const ConstraintType& t : rulesOnlyRegistry().constraintTypes()) r.addConstraintType(t);
  r.setOrigin("/plugins/certifies.so", false);
  r.addMatcher({"certifies", &certifyingMatcher});
  r.clearOrigin();
  r.freeze();
  const Solution s = solve(pointOnPoint(), r);
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_FALSE(s.complete);
  EXPECT_NE(s.message.find("from matcher 'certifies' (plugin /plugins/certifies.so) is unusable: "
                           "a matcher's branch is not exact"),
            std::string::npos)
      << s.message;
}

TEST(Fallback, IsNotCalledForWhatTheRulesAnswer) {
  TestFallback stage;
  const Registry reg = builtinsWithFallback(stage);
  const Solution solved = solve(pointOnPoint(), reg);
  const Solution none = solve(pointsTooFarApart(), reg);
  EXPECT_EQ(solved.status, Status::kSolved);
  EXPECT_EQ(none.status, Status::kInconsistent);
  EXPECT_EQ(stage.calls, 0);
}

TEST(Fallback, AnswersWhatTheRulesLeaveWithACertifiedBranch) {
  TestFallback stage;
  stage.pose = platformPose();
  const Registry reg = builtinsWithFallback(stage);
  const Problem p = platformProblem(stage.pose);
  const Solution s = solve(p, reg);
  EXPECT_EQ(stage.calls, 1);
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(s.message, "");  // a solved answer says nothing, whatever the rules said before
  ASSERT_EQ(s.branches.size(), 1u);
  const Branch& b = s.branches[0];
  EXPECT_FALSE(b.exact);
  EXPECT_EQ(b.certified.radius, 1e-12);
  EXPECT_EQ(b.certified.angle, 2e-12);
  EXPECT_EQ(b.origin, nullptr);  // a built-in stage: no plugin to name
  EXPECT_TRUE(b.manifold->pose(Params{}).isApprox(stage.pose, 1e-12));
  // The pose meets every constraint by the tests' own reading of docs/spec.md §1.9.
  EXPECT_LT(worstSampledViolation(p, s, 1, 1), 1e-9);
  // The claim of completeness is the stage's: a stage that cannot prove it says so.
  TestFallback unproven;
  unproven.pose = stage.pose;
  unproven.complete = false;
  const Solution partial = solve(p, builtinsWithFallback(unproven));
  EXPECT_EQ(partial.status, Status::kSolved);
  EXPECT_FALSE(partial.complete);
}

TEST(Fallback, AProvenInconsistencyIsCompleteAndNamesTheConstraints) {
  TestFallback stage;
  stage.answer = TestFallback::Answer::kInconsistent;
  const Problem p = platformProblem(platformPose());
  const Solution s = solve(p, builtinsWithFallback(stage));
  ASSERT_EQ(s.status, Status::kInconsistent) << s.message;
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(s.conflicts.size(), p.constraints.size());  // it named none: every one
  EXPECT_NE(s.message.find("test-stage"), std::string::npos) << s.message;
}

// A stage that throws, or declines with a reason of its own: the rules' answer stands, their reason
// first.
TEST(Fallback, AThrowOrADeclineLeavesTheRulesAnswerWithTheReason) {
  const Problem p = platformProblem(platformPose());
  const Solution rules = solve(p, rulesOnlyRegistry());
  const struct {
    TestFallback::Answer answer;
    std::string added;
  } cases[] = {
      {TestFallback::Answer::kThrow,
       "; the numeric stage 'test-stage' (built-in) threw: the tracker lost a path"},
      {TestFallback::Answer::kDecline,
       "; the numeric stage 'test-stage' (built-in): 3 of 40 roots not certified"},
  };
  for (const auto& c : cases) {
    TestFallback stage;
    stage.answer = c.answer;
    const Solution s = solve(p, builtinsWithFallback(stage));
    EXPECT_EQ(stage.calls, 1);
    EXPECT_EQ(s.status, Status::kUnhandled);
    EXPECT_FALSE(s.complete);
    EXPECT_TRUE(s.branches.empty());
    EXPECT_EQ(s.message, rules.message + c.added);
  }
}

TEST(Fallback, ACertificateThatIsNotANumberIsRefused) {
  TestFallback stage;
  stage.answer = TestFallback::Answer::kNaNCertificate;
  stage.pose = platformPose();
  const Solution s = solve(platformProblem(stage.pose), builtinsWithFallback(stage));
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_TRUE(s.branches.empty());
  EXPECT_NE(s.message.find("made branch 0 with a certificate that is not finite and non-negative"),
            std::string::npos)
      << s.message;
}

// The last check (§6.5) holds the stage's branches to the constraints as it holds the rules'.
TEST(Fallback, ACertifiedPoseThatBreaksAConstraintIsNotReturned) {
  TestFallback stage;
  stage.pose = platformPose();
  stage.pose.translation().z() += 1e-3;  // off every sphere
  const Solution s = solve(platformProblem(platformPose()), builtinsWithFallback(stage));
  EXPECT_EQ(stage.calls, 1);
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_FALSE(s.complete);
  EXPECT_TRUE(s.branches.empty());
  EXPECT_NE(
      s.message.find("the numeric stage 'test-stage' (built-in): numerical breakdown: branch 0 "
                     "breaks constraint"),
      std::string::npos)
      << s.message;
}

TEST(Fallback, IsNotCalledWithSolverOptionsTheSolverRefuses) {
  TestFallback stage;
  SolverOptions bad;
  bad.max_branches = 0;
  const Solution s = solve(platformProblem(platformPose()), builtinsWithFallback(stage), bad);
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_EQ(stage.calls, 0);
}

}  // namespace
}  // namespace relpos::test
