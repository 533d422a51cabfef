// The tests' own references checked against the literature before anything is checked against
// them: the 40 poses PHCpack's stewgou40 demo lists for Dietmaier's platform hold every constraint
// of data/complete/stewart-gough-dietmaier-40.json (the transcription is right), the random-start
// Newton reference finds each of them and no other, the reference counts what the literature
// states, and the interval check proves a true pose and refuses a displaced one.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "benchmark_problems.hpp"
#include "evaluator.hpp"
#include "interval_check.hpp"
#include "reference_roots.hpp"
#include "relpos/core/manifold.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

// The literature's poses: matrices rounded to 15 digits, re-orthonormalised here.
std::vector<Isometry3d> dietmaierLiteraturePoses() {
  std::ifstream in(RELPOS_DATA_DIR "/complete/stewart-gough-dietmaier-40.literature-poses.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  std::vector<Isometry3d> out;
  for (const auto& pose : j.at("poses")) {
    Eigen::Matrix4d M;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) M(r, c) = pose.at("matrix").at(r).at(c).get<double>();
    Isometry3d X = Isometry3d::Identity();
    X.linear() = Quaterniond(Matrix3d(M.block<3, 3>(0, 0))).normalized().toRotationMatrix();
    X.translation() = M.block<3, 1>(0, 3);
    out.push_back(X);
  }
  return out;
}

TEST(ReferenceCheck, DietmaierLiteraturePosesHoldEveryLeg) {
  const Problem p = loadComplete("stewart-gough-dietmaier-40.json");
  const std::vector<Isometry3d> poses = dietmaierLiteraturePoses();
  ASSERT_EQ(poses.size(), 40u);
  for (std::size_t i = 0; i < poses.size(); ++i)
    EXPECT_LT(worstViolation(p, poses[i]), 1e-8) << "literature pose " << i + 1;
}

TEST(ReferenceCheck, NewtonReferenceFindsExactlyTheLiteraturePoses) {
  const BenchmarkProblem& b = problemNamed("stewart-gough-dietmaier-40.json");
  const ReferenceRoots& ref = benchmarkReference(b);
  const std::vector<Isometry3d> lit = dietmaierLiteraturePoses();
  EXPECT_EQ(ref.poses.size(), lit.size());
  // The roots are far apart compared with that, so matching to the nearest is unambiguous.
  for (std::size_t i = 0; i < ref.poses.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_GT(poseDistance(ref.poses[i], ref.poses[j]), 1e-2);
  for (std::size_t i = 0; i < lit.size(); ++i) {
    double best = 1e9;
    for (const Isometry3d& X : ref.poses) best = std::min(best, poseDistance(X, lit[i]));
    // The listed poses solve the polynomials with coefficients rounded to 10 digits: the
    // ill-conditioned ones (σmin/σmax ≈ 1e-5) sit a few 1e-6 from the spec's roots.
    EXPECT_LT(best, 1e-4) << "literature pose " << i + 1 << " not in the reference";
  }
}

TEST(ReferenceCheck, ReferenceCountsWhatTheLiteratureStates) {
  for (const BenchmarkProblem& b : benchmarkProblems()) {
    const ReferenceRoots& ref = benchmarkReference(b);
    std::cout << b.file << ": " << ref.poses.size() << " roots from " << ref.converged << " of "
              << ref.starts << " starts\n";
    if (b.literature_count >= 0) {
      EXPECT_EQ(static_cast<int>(ref.poses.size()), b.literature_count)
          << b.file << ": " << b.literature;
    }
    // Every root reached by more than one start: a root found once suggests the starts are too
    // few to trust the count.
    for (std::size_t i = 0; i < ref.hits.size(); ++i)
      EXPECT_GE(ref.hits[i], 2) << b.file << " root " << i << " reached by one start only";
  }
}

TEST(ReferenceCheck, OctahedralRootsComeInMirrorPairs) {
  // The base points lie in z = 0 and so do the platform's: reflecting a pose in the base plane
  // (and the platform in its own) gives another pose, so the real roots pair up.
  for (const char* file : {"octahedral-a.json", "octahedral-b.json"}) {
    const ReferenceRoots& ref = benchmarkReference(problemNamed(file));
    EXPECT_EQ(ref.poses.size() % 2, 0u) << file;
    EXPECT_GT(ref.poses.size(), 0u) << file;
    const Problem p = loadComplete(file);
    const Eigen::DiagonalMatrix<double, 3> Z(1, 1, -1);
    for (const Isometry3d& X : ref.poses) {
      Isometry3d Y = X;
      Y.linear() = Z * X.linear() * Z;
      Y.translation() = Z * X.translation();
      EXPECT_LT(worstViolation(p, Y), 1e-8);
      double best = 1e9;
      for (const Isometry3d& W : ref.poses) best = std::min(best, poseDistance(W, Y));
      EXPECT_LT(best, 1e-6) << file << ": the mirror of a root is not in the reference";
    }
  }
}

TEST(ReferenceCheck, IntervalCheckProvesTrueRootsAndRefusesDisplacedPoses) {
  for (const BenchmarkProblem& b : benchmarkProblems()) {
    const Problem p = loadComplete(b.file);
    const ReferenceRoots& ref = benchmarkReference(b);
    ASSERT_FALSE(ref.poses.empty()) << b.file;
    for (std::size_t i = 0; i < ref.poses.size(); ++i) {
      IntervalBox box{1e-7, 1e-7, b.line_quotient};
      const IntervalVerdict v = provesSolutionInBox(p, ref.poses[i], box);
      EXPECT_TRUE(v.proven) << b.file << " root " << i << ": " << v.why;
      // Moved 1e-4 along x: no root within 1e-6 of it (the nearest is 1e-4 away).
      Isometry3d moved = ref.poses[i];
      moved.translation().x() += 1e-4;
      box = {1e-6, 1e-6, b.line_quotient};
      EXPECT_FALSE(provesSolutionWithin(p, moved, box).proven) << b.file << " root " << i;
    }
  }
}

TEST(ReferenceCheck, IntervalCheckFollowsTheFixedPose) {
  // The fixed object moved and turned: every root moves with it, and is proven there.
  Problem p = loadComplete("stewart-gough-dietmaier-40.json");
  const ReferenceRoots& ref = benchmarkReference(problemNamed("stewart-gough-dietmaier-40.json"));
  Isometry3d T = Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  T.translation() = Vector3d(3, -1, 2);
  p.fixed.pose = T;
  for (std::size_t i = 0; i < ref.poses.size(); ++i) {
    EXPECT_LT(worstViolation(p, T * ref.poses[i]), 1e-9);
    const IntervalVerdict v = provesSolutionInBox(p, T * ref.poses[i], {1e-7, 1e-7, false});
    EXPECT_TRUE(v.proven) << "root " << i << ": " << v.why;
    EXPECT_FALSE(provesSolutionWithin(p, ref.poses[i], {1e-6, 1e-6, false}).proven) << i;
  }
}

}  // namespace
}  // namespace relpos::test
