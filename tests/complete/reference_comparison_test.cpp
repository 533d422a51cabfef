// The benchmark checks (reference_comparison.hpp) tested on solutions made from the reference:
// the reference itself passes; one with a root left out, a branch twice, a pose moved, or the
// four-spheres lines in one direction only fails, each with the failure it should name.
#include "reference_comparison.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "benchmark_problems.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::test {
namespace {

// A 0-DOF branch at one pose.
class FixedPose final : public ManifoldBase<FixedPose> {
 public:
  explicit FixedPose(const Isometry3d& X) : X_(X) {}
  const char* typeName() const override { return "test FixedPose"; }
  int dof() const override { return 0; }
  int rotationalDof() const override { return 0; }
  int translationalDof() const override { return 0; }
  Parameter parameter(int) const override { return {}; }
  Isometry3d pose(const Params&) const override { return X_; }
  Params project(const Isometry3d&) const override { return Params{}; }
  std::string describe() const override { return "fixed pose"; }

 private:
  Isometry3d X_;
};

// The 2-DOF set of poses X·spin(φ)·slide(s) about the mobile line (point a, direction m).
class LineStabiliser final : public ManifoldBase<LineStabiliser> {
 public:
  LineStabiliser(const Isometry3d& X, const Vector3d& a, const Vector3d& m) : X_(X), a_(a), m_(m) {}
  const char* typeName() const override { return "test LineStabiliser"; }
  int dof() const override { return 2; }
  int rotationalDof() const override { return 1; }
  int translationalDof() const override { return 1; }
  Parameter parameter(int i) const override {
    if (i == 0) return {"spin", ParamKind::kAngle, -kPi, kPi, true};
    const double inf = std::numeric_limits<double>::infinity();
    return {"slide", ParamKind::kLength, -inf, inf, false};
  }
  Isometry3d pose(const Params& t) const override {
    Isometry3d Y = Isometry3d::Identity();
    Y.linear() = Eigen::AngleAxisd(t[0], m_).toRotationMatrix();
    Y.translation() = a_ - Y.linear() * a_ + t[1] * m_;
    return X_ * Y;
  }
  Params project(const Isometry3d& X) const override {
    const Isometry3d Y = X_.inverse() * X;
    const Eigen::AngleAxisd r(Y.linear());
    Params t{};
    t[0] = r.angle() * (r.axis().dot(m_) >= 0 ? 1.0 : -1.0);
    t[1] = (Y * a_ - a_).dot(m_);
    return t;
  }
  std::string describe() const override { return "line stabiliser"; }

 private:
  Isometry3d X_;
  Vector3d a_, m_;
};

Solution fixedPoses(const std::vector<Isometry3d>& poses) {
  Solution s;
  s.status = Status::kSolved;
  for (const Isometry3d& X : poses) {
    Branch b;
    b.manifold.emplace<FixedPose>(X);
    s.branches.push_back(b);
  }
  return s;
}

bool mentions(const std::vector<std::string>& failures, const std::string& what) {
  for (const std::string& f : failures)
    if (f.find(what) != std::string::npos) return true;
  return false;
}

TEST(ReferenceComparison, PosesPassOnlyWhenAllThereOnceAndRight) {
  const BenchmarkProblem& b = problemNamed("octahedral-b.json");
  const Problem p = loadComplete(b.file);
  const ReferenceRoots& ref = benchmarkReference(b);
  ASSERT_GE(ref.poses.size(), 2u);
  EXPECT_TRUE(compareWithReference(p, fixedPoses(ref.poses), ref, false).empty());

  std::vector<Isometry3d> dropped(ref.poses.begin(), ref.poses.end() - 1);
  std::vector<std::string> f = compareWithReference(p, fixedPoses(dropped), ref, false);
  EXPECT_TRUE(mentions(f, "is on no branch")) << testing::PrintToString(f);
  EXPECT_TRUE(mentions(f, "branches, the reference has"));

  std::vector<Isometry3d> twice = ref.poses;
  twice.back() = twice.front();
  f = compareWithReference(p, fixedPoses(twice), ref, false);
  EXPECT_TRUE(mentions(f, "are the same pose")) << testing::PrintToString(f);

  std::vector<Isometry3d> moved = ref.poses;
  moved[0].translation().x() += 1e-3;
  f = compareWithReference(p, fixedPoses(moved), ref, false);
  EXPECT_TRUE(mentions(f, "violates a constraint")) << testing::PrintToString(f);
}

TEST(ReferenceComparison, LinesNeedBothDirections) {
  const BenchmarkProblem& b = problemNamed("four-spheres-12-lines.json");
  const Problem p = loadComplete(b.file);
  const ReferenceRoots& ref = benchmarkReference(b);
  const InputConstraint& c = p.constraints[0];
  Solution both, one;
  both.status = one.status = Status::kSolved;
  for (const Isometry3d& X : ref.poses)
    for (const Isometry3d& Y : {X, Isometry3d(X * lineFlip(p))}) {
      Branch br;
      br.manifold.emplace<LineStabiliser>(Y, c.mobile.point, c.mobile.direction);
      both.branches.push_back(br);
      if (Y.isApprox(X)) one.branches.push_back(br);
    }
  const std::vector<std::string> ok = compareWithReference(p, both, ref, true);
  EXPECT_TRUE(ok.empty()) << testing::PrintToString(ok);
  const std::vector<std::string> f = compareWithReference(p, one, ref, true);
  EXPECT_TRUE(mentions(f, "reversed, is on no branch")) << testing::PrintToString(f);
  EXPECT_FALSE(mentions(f, "distinct lines"));  // every line is there, in one direction
}

}  // namespace
}  // namespace relpos::test
