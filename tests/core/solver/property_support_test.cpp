// The property tests' own support, checked on its own: the spec writer round-trips, the
// transforms are the same problem (and undo), and the result checker does flag a wrong answer —
// so that once the solver passes the property tests, a checker that flags nothing cannot hide
// behind them.
#include <gtest/gtest.h>

#include "pin_manifold.hpp"
#include "problem_transforms.hpp"
#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "result_checker.hpp"
#include "solve_helpers.hpp"
#include "spec_writer.hpp"

namespace relpos::test {
namespace {

// A mobile point at a distance from a fixed point and on a fixed plane: a circle, solved.
KnownProblem sample(std::uint64_t seed) {
  Rng rng(seed);
  KnownProblem kp = emptyKnownProblem(rng);
  const auto& kinds = singleKinds();
  addConstraint(kp, kinds[0], rng);  // distance point-point
  const NamedFeature point = kp.problem.mobile.features.back();
  addConstraint(kp, kinds[14], rng, false, &point);  // coincident plane(f)-point(m)
  return kp;
}

double worstFeatureGap(const Problem& a, const Problem& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.constraints.size(); ++i)
    for (bool fixed : {true, false}) {
      const Feature& fa = fixed ? a.constraints[i].fixed : a.constraints[i].mobile;
      const Feature& fb = fixed ? b.constraints[i].fixed : b.constraints[i].mobile;
      worst = std::max({worst, (fa.point - fb.point).norm(), std::abs(fa.radius - fb.radius)});
      if (fa.kind != FeatureKind::kPoint)  // a point's direction means nothing
        worst = std::max(worst, (fa.direction - fb.direction).norm());
    }
  return worst;
}

TEST(PropertySupport, SpecWriterRoundTrips) {
  const KnownProblem kp = sample(1);
  const Problem p = canonical(kp.problem);
  ASSERT_EQ(p.constraints.size(), kp.problem.constraints.size());
  EXPECT_LT(worstFeatureGap(p, kp.problem), 1e-14);
  EXPECT_LT(poseDistance(p.fixed.pose, kp.problem.fixed.pose), 1e-14);
  EXPECT_LT(poseDistance(p.mobile.pose, kp.problem.mobile.pose), 1e-14);
  EXPECT_EQ(p.constraints[0].value, kp.problem.constraints[0].value);
  // The text is exactly the problem solved: read again, it gives the same numbers.
  const WrittenSpec w = written(kp.problem);
  const Problem again = parseSpec(w.text, builtinRegistry(), "again").problem.value();
  EXPECT_EQ(worstFeatureGap(again, w.problem), 0.0);
  EXPECT_TRUE(again.fixed.pose.isApprox(w.problem.fixed.pose, 0.0));
  EXPECT_TRUE(again.mobile.pose.isApprox(w.problem.mobile.pose, 0.0));
}

TEST(PropertySupport, TransformsKeepTheKnownPoseAndTheSize) {
  const KnownProblem kp = sample(2);
  const Problem p = canonical(kp.problem);
  const double size = problemSize(p);
  for (const ProblemTransform& t : invarianceTransforms()) {
    SCOPED_TRACE(t.label);
    const Problem q = t.apply(p);
    EXPECT_NEAR(problemSize(q), size * t.lengthFactor(), 1e-9 * size * t.lengthFactor());
    const double v =
        RelativeEvaluator(q, size * t.lengthFactor()).worst(t.applyToPose(kp.X_WM_star));
    EXPECT_LT(v, 1e-8);
    // A pose that is not a solution stays one that is not.
    Isometry3d off = kp.X_WM_star;
    off.translation() += 1e-3 * size * Vector3d(1, 2, 2) / 3.0;
    EXPECT_GT(RelativeEvaluator(q, size * t.lengthFactor()).worst(t.applyToPose(off)), 1e-4);
  }
  // Scaling undoes.
  const Problem back = ProblemTransform::scale(1e6).apply(ProblemTransform::scale(1e-6).apply(p));
  EXPECT_LT(worstFeatureGap(back, p), 1e-14 * size);
}

TEST(PropertySupport, CheckerFlagsAWrongAnswer) {
  const KnownProblem kp = sample(3);
  const Problem p = canonical(kp.problem);
  const Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved) << describeBranches(s);
  CheckOptions opt;
  opt.known = &kp.X_WM_star;
  const CheckReport good = checkSolution(p, s, opt);
  EXPECT_TRUE(good.ok()) << good.summary();
  // The same branches judged against a problem whose distance is 1e-4 of the size longer: every
  // pose of them violates it, and the known pose of that problem is on none of them.
  Problem longer = p;
  longer.constraints[0].value += 1e-4 * problemSize(p);
  longer.constraints[0].min = longer.constraints[0].max = longer.constraints[0].value;
  const CheckReport bad = checkSolution(longer, s, CheckOptions());
  EXPECT_FALSE(bad.violating.empty());
  EXPECT_GT(bad.worst_violation, 5e-5);
  Isometry3d elsewhere = kp.X_WM_star;
  elsewhere.translation() += 1e-3 * problemSize(p) * Vector3d(2, -1, 2) / 3.0;
  opt.known = &elsewhere;
  const CheckReport lost = checkSolution(p, s, opt);
  EXPECT_FALSE(lost.known_lost.empty());
  EXPECT_FALSE(lost.ok());
}

TEST(PropertySupport, CheckerFlagsANearestFalselySaidGlobal) {
  Problem p;
  p.fixed.features.push_back({"F", Feature::makePoint(Vector3d(1, 0, 0))});
  p.mobile.features.push_back({"M", Feature::makePoint(Vector3d(5, 0, 0))});
  InputConstraint c;
  c.type = "coincident";
  c.fixed = p.fixed.features[0].feature, c.mobile = p.mobile.features[0].feature;
  c.fixed_name = "F", c.mobile_name = "M";
  p.constraints.push_back(c);
  // A pin claiming a coupling of 1 (pin_manifold.hpp); the initial pose: its rotation at turn 0,
  // moved 0.3 along y (a turn of −0.06 brings it back for 0.06 rad).
  p.mobile.pose = PinManifold(1.0).pose(Params{});
  p.mobile.pose.translation() += Vector3d(0, 0.3, 0);
  Solution s;
  s.status = Status::kSolved;
  s.branches.emplace_back();
  s.branches.back().manifold.emplace<PinManifold>(1.0);
  s.branches.back().sources = 1;
  CheckOptions opt;
  opt.samples_per_branch = 200;
  const CheckReport rep = checkSolution(p, s, opt);
  EXPECT_TRUE(rep.violating.empty()) << rep.summary();  // its poses are the problem's
  EXPECT_FALSE(rep.false_global.empty());
  EXPECT_FALSE(rep.ok());
}

}  // namespace
}  // namespace relpos::test
