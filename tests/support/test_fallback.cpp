#include "test_fallback.hpp"

#include <limits>
#include <stdexcept>

#include "relpos/builtins/builtins.hpp"
#include "relpos/complete/register.hpp"
#include "relpos/manifolds/separable.hpp"

namespace relpos::test {
namespace {

bool answer(const Problem& problem, const Registry&, const Tolerance&, Solution& solution,
            const void* context) {
  const auto& stage = *static_cast<const TestFallback*>(context);
  ++stage.calls;
  switch (stage.answer) {
    case TestFallback::Answer::kThrow:
      throw std::runtime_error("the tracker lost a path");
    case TestFallback::Answer::kDecline:
      solution.message = "3 of 40 roots not certified";
      return false;
    case TestFallback::Answer::kInconsistent:
      solution.status = Status::kInconsistent;
      solution.message = "";  // the solver names every constraint and says why
      return true;
    case TestFallback::Answer::kPose:
    case TestFallback::Answer::kNaNCertificate:
      break;
  }
  // The pose as a 0-DOF branch: rotation fixed, the mobile origin on the pose's translation.
  const manifolds::translation::Point at(
      Fundamental::pointPoint(Vector3d::Zero(), stage.pose.translation(), 0.0, 1));
  solution.branches.emplace_back();
  Branch& b = solution.branches.back();
  b.manifold.emplace<manifolds::SeparableManifold>(manifolds::rotation::Fixed(stage.pose.linear()),
                                                   at);
  for (std::size_t i = 0; i < problem.constraints.size(); ++i) b.sources |= SourceMask{1} << i;
  b.exact = false;
  b.certified = stage.certificate;
  if (stage.answer == TestFallback::Answer::kNaNCertificate)
    b.certified.radius = std::numeric_limits<double>::quiet_NaN();
  solution.status = Status::kSolved;
  solution.complete = stage.complete;
  return true;
}

// Every item of the built-ins but a numeric stage, into `to` (not frozen).
void addRules(Registry& to) {
  Registry from;
  registerBuiltins(from);
  for (const ConstraintType& t : from.constraintTypes()) to.addConstraintType(t);
  for (const RuleInfo& r : from.rules()) to.addRule(r);
  for (const ManifoldInfo& m : from.manifolds()) to.addManifold(m);
  for (const MatcherInfo& m : from.matchers()) to.addMatcher(m);
}

}  // namespace

const Registry& rulesOnlyRegistry() {
  static const Registry registry = [] {
    Registry r;
    addRules(r);
    r.freeze();
    return r;
  }();
  return registry;
}

const Registry& sweepRegistry() {
  static const Registry registry = [] {
    Registry r;
    addRules(r);
    complete::StageOptions options;
    options.compute_start_systems = false;
    // the charts' descent from fewer starts, fewer charts (docs/spec.md §8.7): the sweeps check
    // every answer's soundness, thousands of solves each, ten seed offsets, also under the
    // sanitizers — within the CI's budget
    options.set_starts = 6;
    options.max_charts = 3;
    complete::registerStage(r, options);
    r.freeze();
    return r;
  }();
  return registry;
}

Registry builtinsWithFallback(const TestFallback& stage) {
  Registry r;
  addRules(r);
  r.setFallback({"test-stage", &answer, &stage});
  r.freeze();
  return r;
}

Isometry3d platformPose() {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  X.translation() = Vector3d(0.5, 0.7, 2.0);
  return X;
}

Problem platformProblem(const Isometry3d& X_WM) {
  Problem p;
  p.name = "platform-3-3";
  const Vector3d fixed[3] = {{0, 0, 0}, {4, 0, 0}, {1, 3, 0}};
  const Vector3d mobile[3] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const char* fixed_names[3] = {"A", "B", "C"};
  const char* mobile_names[3] = {"a", "b", "c"};
  for (int i = 0; i < 3; ++i) {
    p.addFixedFeature(fixed_names[i], Feature::makePoint(fixed[i]));
    p.addMobileFeature(mobile_names[i], Feature::makePoint(mobile[i]));
  }
  // a-A, a-B, b-B, b-C, c-C, c-A: each mobile point on two spheres.
  const int pairs[6][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {0, 2}};
  for (const auto& [f, m] : pairs)
    p.addConstraint("distance", fixed_names[f], mobile_names[m],
                    (fixed[f] - X_WM * mobile[m]).norm());
  return p;
}

}  // namespace relpos::test
