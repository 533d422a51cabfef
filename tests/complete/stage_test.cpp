// The numeric stage end to end (complete/stage.hpp): problems built around a known pose (a 6-6
// platform, the octahedral manipulator, mixed kinds, the four spheres) are solved with every
// root of their family certified, the known pose among the branches; a problem no pose meets is
// proven inconsistent; a scaled and moved copy gives the same poses, mapped.
#include "relpos/complete/stage.hpp"

#include <gtest/gtest.h>

#include "known_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "test_fallback.hpp"

namespace relpos::complete {
namespace {

using test::randomPose;
using test::randomVector;

Tolerance toleranceOf(const Problem& p) { return Tolerance::forScale(2.0 * p.lengthScale()); }

// The branch whose pose (at its reference parameters) is nearest X, and how near.
double nearestBranch(const Solution& s, const Isometry3d& X) {
  double best = std::numeric_limits<double>::infinity();
  for (const Branch& b : s.branches) {
    const Isometry3d Y = b.manifold->pose(referenceParams(*b.manifold));
    best = std::min(best, poseDistance(X, Y));
  }
  return best;
}

void expectCertificates(const Solution& s, const StageReport& r) {
  ASSERT_EQ(r.certificates.size(), s.branches.size());
  EXPECT_FALSE(s.complete);  // positive-dimensional sets are not excluded
  for (std::size_t i = 0; i < s.branches.size(); ++i) {
    const auto& c = r.certificates[i];
    EXPECT_GE(c.radius, 0.0);
    EXPECT_GE(c.angle, 0.0);
    EXPECT_LT(c.radius, 1e-6);
    EXPECT_LT(c.angle, 1e-6);
    EXPECT_FALSE(s.branches[i].exact);
    EXPECT_EQ(s.branches[i].certified.radius, c.radius);
    EXPECT_EQ(s.branches[i].certified.angle, c.angle);
  }
}

// The built-ins register this stage as their numeric stage (complete::registerStage); the
// rules' own answer is that of a registry without it.
const Registry& registryWithStage() { return builtinRegistry(); }
const Registry& rulesOnly() { return relpos::test::rulesOnlyRegistry(); }

TEST(Stage, SixSixPlatformHasItsFortyRootsAndTheTruePose) {
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 3; ++trial) {
    const Isometry3d X = randomPose(rng);
    Problem p = test::sixSix(rng, X);
    if (trial == 2) {  // a fixed frame of its own: the fixed points are placed by it
      p.fixed.pose = randomPose(rng);
      for (InputConstraint& c : p.constraints) c.fixed = c.fixed.placed(p.fixed.pose.inverse());
    }
    Solution s;
    StageReport r;
    ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
    EXPECT_EQ(s.status, Status::kSolved);
    EXPECT_EQ(r.root_count, 40);
    EXPECT_EQ(r.roots_found, r.root_count) << r.roots_found << " of " << r.root_count;
    EXPECT_EQ(static_cast<int>(s.branches.size()), r.real_roots);
    EXPECT_EQ(r.real_roots % 2, 0);  // complex roots come in conjugate pairs: 40 − real is even
    EXPECT_LT(nearestBranch(s, X), 1e-8);
    expectCertificates(s, r);
    for (const Branch& b : s.branches) EXPECT_EQ(b.manifold->dof(), 0);
  }
}

TEST(Stage, OctahedralManipulatorIsItsOwnSixteenRootFamily) {
  std::mt19937_64 rng(32);
  const Isometry3d X = randomPose(rng);
  const Problem p = test::octahedral(rng, X);
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(r.root_count, 16);
  EXPECT_EQ(r.roots_found, r.root_count);
  EXPECT_LT(nearestBranch(s, X), 1e-8);
  expectCertificates(s, r);
}

TEST(Stage, MixedKindsFindTheTruePose) {
  std::mt19937_64 rng(33);
  for (int k = 0; k < test::kMixedProblems; ++k) {
    const Isometry3d X = randomPose(rng);
    const Problem p = test::mixed(k, rng, X);
    Solution s;
    StageReport r;
    ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r))
        << p.name << ": " << s.message;
    EXPECT_EQ(r.roots_found, r.root_count)
        << p.name << ": " << r.roots_found << " of " << r.root_count;
    EXPECT_LT(nearestBranch(s, X), 1e-8) << p.name;
    expectCertificates(s, r);
  }
}

TEST(Stage, FourSpheresGiveTwelveLinesEachBothWays) {
  std::mt19937_64 rng(34);
  const Vector3d w = randomVector(rng).normalized(), q = 0.3 * randomVector(rng);
  const Problem p = test::fourSpheres(rng, q, w);
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(r.root_count, 24);
  EXPECT_EQ(r.roots_found, r.root_count);
  EXPECT_EQ(r.real_roots % 2, 0);
  // Every line proven listed: the interval search found no real line but these.
  EXPECT_TRUE(r.real_complete) << r.real_doubt;
  EXPECT_TRUE(s.complete);
  EXPECT_GT(r.proof_boxes, 0);
  bool found = false;
  for (const Branch& b : s.branches) {
    EXPECT_EQ(b.manifold->dof(), 2);  // the spin about the line and the slide along it
    const Isometry3d Y = b.manifold->pose(referenceParams(*b.manifold));
    const Vector3d dir = Y.linear() * Vector3d::UnitZ();
    const Vector3d at = Y.translation();
    if ((dir - w).norm() < 1e-8 && (at - q).cross(w).norm() < 1e-8) found = true;
  }
  EXPECT_TRUE(found);
}

// A line at given angles to two fixed lines and given distances from two fixed points.
TEST(Stage, ALineAtTwoAnglesAndTwoDistances) {
  std::mt19937_64 rng(38);
  const Vector3d w = randomVector(rng).normalized(), q = 0.3 * randomVector(rng);
  Problem p;
  p.addMobileFeature("axis", Feature::makeLine(Vector3d(0.1, 0.2, 0.3), -Vector3d::UnitZ()));
  p.addMobileFeature("axis2", Feature::makeLine(Vector3d(0.1, 0.2, 1.3), Vector3d::UnitZ()));
  for (int i = 0; i < 2; ++i) {
    const Vector3d a = randomVector(rng), u = randomVector(rng).normalized();
    p.addFixedFeature("L" + std::to_string(i), Feature::makeLine(a, u));
    // The mobile line's direction is -w for "axis" (its direction is -z): arccos(u·(-w)).
    p.addConstraint("angle", "L" + std::to_string(i), i == 0 ? "axis" : "axis2",
                    std::acos(u.dot(i == 0 ? -w : w)));
    const Vector3d s = 2.0 * randomVector(rng);
    p.addFixedFeature("S" + std::to_string(i), Feature::makePoint(s));
    p.addConstraint("distance", "S" + std::to_string(i), "axis2", (s - q).cross(w).norm());
  }
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(r.roots_found, r.root_count) << r.roots_found << " of " << r.root_count;
  bool found = false;
  for (const Branch& b : s.branches) {
    EXPECT_EQ(b.manifold->dof(), 2);
    const Isometry3d Y = b.manifold->pose(referenceParams(*b.manifold));
    const Vector3d dir = Y.linear() * Vector3d::UnitZ();
    if ((dir - w).norm() < 1e-8 && (Y * Vector3d(0.1, 0.2, 0.3) - q).cross(w).norm() < 1e-8)
      found = true;
  }
  EXPECT_TRUE(found);
}

// A cylinder tangent to two planes: its axis along their corner, both ways (two roots), each a
// spin and slide.
TEST(Stage, CylinderInACorner) {
  Problem p;
  p.addFixedFeature("floor", Feature::makePlane(Vector3d::Zero(), Vector3d(0, 0, -1)));
  p.addFixedFeature("wall", Feature::makePlane(Vector3d::Zero(), Vector3d(0, -1, 0)));
  p.addMobileFeature("C", Feature::makeCylinder(Vector3d(0, 0, 0.5), Vector3d::UnitZ(), 0.25));
  p.addConstraint("tangent", "floor", "C", 0.0, Orientation::kAligned);
  p.addConstraint("tangent", "wall", "C", 0.0, Orientation::kAligned);
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(r.root_count, 2);
  EXPECT_EQ(r.roots_found, r.root_count);
  ASSERT_EQ(s.branches.size(), 2u);
  for (const Branch& b : s.branches) {
    EXPECT_EQ(b.manifold->dof(), 2);
    const Isometry3d Y = b.manifold->pose(referenceParams(*b.manifold));
    // The axis along x, 0.25 above the floor and 0.25 off the wall.
    EXPECT_LT((Y.linear() * Vector3d::UnitZ()).cross(Vector3d::UnitX()).norm(), 1e-9);
    const Vector3d on = Y * Vector3d(0, 0, 0.5);
    EXPECT_NEAR(on.z(), 0.25, 1e-9);
    EXPECT_NEAR(on.y(), 0.25, 1e-9);
  }
}

// Six legs of 0.1 between fixed points 10 apart and mobile ones 1 apart: no pose. Every isolated
// root is found and none is real; the legs alone bound the translation to boxes that do not
// meet: proven inconsistent. Without the proof (a budget of one box), the stage declines.
Problem legsTooShort() {
  std::mt19937_64 rng(35);
  Problem p;
  for (int i = 0; i < 6; ++i) {
    p.addFixedFeature("A" + std::to_string(i), Feature::makePoint(10.0 * randomVector(rng)));
    p.addMobileFeature("B" + std::to_string(i), Feature::makePoint(randomVector(rng)));
    p.addConstraint("distance", "A" + std::to_string(i), "B" + std::to_string(i), 0.1);
  }
  return p;
}

TEST(Stage, NoPoseIsProvenInconsistent) {
  const Problem p = legsTooShort();
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(s.status, Status::kInconsistent);
  EXPECT_TRUE(s.complete);
  EXPECT_EQ(r.roots_found, r.root_count);
  EXPECT_EQ(r.real_roots, 0);
  EXPECT_TRUE(s.branches.empty());
  EXPECT_NE(s.message.find("no pose satisfies"), std::string::npos) << s.message;
  // Through solve(): inconsistent too (here the rules see it first, in two of the legs).
  EXPECT_EQ(solve(p, registryWithStage()).status, Status::kInconsistent);
}

TEST(Stage, NoPoseWithoutAProofIsNotClaimedInconsistent) {
  const Problem p = legsTooShort();
  StageOptions options;
  options.pose_proof_boxes = 0;
  Solution s;
  StageReport r;
  EXPECT_FALSE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r, options));
  EXPECT_EQ(r.real_roots, 0);
  EXPECT_NE(s.message.find("no proof"), std::string::npos) << s.message;
  EXPECT_TRUE(s.branches.empty());
}

// Lines within 0.1 of four points about 2.8 apart: none. Proven by the search over directions.
TEST(Stage, NoLineIsProvenInconsistent) {
  Problem p;
  p.addMobileFeature("l", Feature::makeLine(Vector3d::Zero(), Vector3d::UnitZ()));
  const Vector3d c[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (int i = 0; i < 4; ++i) {
    p.addFixedFeature("c" + std::to_string(i), Feature::makePoint(c[i]));
    p.addConstraint("distance", "c" + std::to_string(i), "l", 0.1);
  }
  Solution s;
  StageReport r;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r)) << s.message;
  EXPECT_EQ(s.status, Status::kInconsistent);
  EXPECT_EQ(r.real_roots, 0);
  EXPECT_GT(r.proof_boxes, 0);
}

// Four points on one axis, a line at distance 1 from each: every line parallel to the axis at
// distance 1 (a cylinder's rulings), a curve of lines that no count of isolated roots sees.
// Never complete, never inconsistent.
TEST(Stage, ACurveOfLinesIsNeverComplete) {
  Problem p;
  p.addMobileFeature("l", Feature::makeLine(Vector3d::Zero(), Vector3d::UnitZ()));
  for (int i = 0; i < 4; ++i) {
    p.addFixedFeature("c" + std::to_string(i), Feature::makePoint(Vector3d(0, 0, 0.7 * i)));
    p.addConstraint("distance", "c" + std::to_string(i), "l", 1.0);
  }
  Solution s;
  StageReport r;
  solveComplete(p, builtinRegistry(), toleranceOf(p), s, &r);
  EXPECT_NE(s.status, Status::kInconsistent) << s.message;
  EXPECT_FALSE(s.complete);
  EXPECT_FALSE(r.real_complete);
  const Solution t = solve(p, registryWithStage());
  EXPECT_NE(t.status, Status::kInconsistent) << t.message;
  EXPECT_FALSE(t.complete);
}

TEST(Stage, AScaledAndMovedCopyGivesTheSamePosesMapped) {
  std::mt19937_64 rng(36);
  const Isometry3d X = randomPose(rng);
  const Problem p = test::sixSix(rng, X);
  const double scale = 250.0;
  const Vector3d dW(100, -40, 7), dM(-3, 2, 9);
  const Problem q = test::scaledAndMoved(p, scale, dW, dM);
  Solution a, b;
  StageReport ra, rb;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), a, &ra));
  ASSERT_TRUE(solveComplete(q, builtinRegistry(), toleranceOf(q), b, &rb));
  ASSERT_EQ(a.branches.size(), b.branches.size());
  for (const Branch& br : a.branches) {
    const Isometry3d Y = test::movedPose(br.manifold->pose({}), scale, dW, dM);
    EXPECT_LT(nearestBranch(b, Y), 1e-7 * scale);
  }
}

// Through solve(): the rules leave the platform unhandled, the stage answers, the solver's last
// check passes every branch.
TEST(Stage, SolveHandsTheRulesLeftoversToTheStage) {
  std::mt19937_64 rng(39);
  const Isometry3d X = randomPose(rng);
  const Problem p = test::sixSix(rng, X);
  const Solution s = solve(p, registryWithStage());
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  EXPECT_FALSE(s.complete);
  EXPECT_LT(nearestBranch(s, X), 1e-8);
  for (const Branch& b : s.branches) {
    EXPECT_FALSE(b.exact);
    EXPECT_LT(b.certified.radius, 1e-6);
  }
  // A problem the stage does not take stays the rules' answer, its reason added.
  Problem q = p;
  q.constraints.pop_back();
  // Five equations: not for the polynomial stage (its reason), a set of poses the charts answer
  // (docs/spec.md §8.7), certified, not complete.
  Solution direct;
  EXPECT_FALSE(solveComplete(q, builtinRegistry(), toleranceOf(q), direct));
  EXPECT_NE(direct.message.find("5 equations"), std::string::npos) << direct.message;
  const Solution u = solve(q, registryWithStage());
  ASSERT_EQ(u.status, Status::kSolved) << u.message;
  EXPECT_FALSE(u.complete);
  for (const Branch& b : u.branches) {
    EXPECT_STREQ(b.manifold->typeName(), "Chart");
    EXPECT_EQ(b.manifold->dof(), 1);
  }
}

// Random problems of 3 to 6 constraints measured at a random pose, which the rules leave
// unhandled: the stage, through solve(), never answers inconsistent (the pose exists), and when
// every isolated root was found the pose is among its branches (these are generic: no
// positive-dimensional set of poses).
TEST(Stage, RandomProblemsTheRulesLeave) {
  std::mt19937_64 rng(41);
  int answered = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Isometry3d X = randomPose(rng);
    Problem p;
    const int k = 3 + static_cast<int>(rng() % 4);
    for (int i = 0; i < k; ++i) test::addRandomConstraint(p, rng, X, i);
    if (solve(p, rulesOnly()).status != Status::kUnhandled) continue;
    const Solution s = solve(p, registryWithStage());
    if (s.status == Status::kUnhandled) continue;
    ++answered;
    ASSERT_EQ(s.status, Status::kSolved) << "trial " << trial << ": " << s.message;
    Solution direct;
    StageReport r;
    if (!solveComplete(p, builtinRegistry(), toleranceOf(p), direct, &r)) {
      // not for the polynomial stage (a set of poses): the charts answered (docs/spec.md §8.7)
      for (const Branch& b : s.branches) EXPECT_STREQ(b.manifold->typeName(), "Chart");
      continue;
    }
    EXPECT_EQ(direct.branches.size(), s.branches.size());
    if (r.complete) {
      EXPECT_LT(nearestBranch(s, X), 1e-7) << "trial " << trial << ": " << r.signature;
    }
  }
  EXPECT_GT(answered, 0);
}

// The same problem twice: the same branches, to the bit (fixed seeds, no clock).
TEST(Stage, Deterministic) {
  std::mt19937_64 rng(40);
  const Problem p = test::octahedral(rng, randomPose(rng));
  Solution a, b;
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), a));
  ASSERT_TRUE(solveComplete(p, builtinRegistry(), toleranceOf(p), b));
  ASSERT_EQ(a.branches.size(), b.branches.size());
  for (std::size_t i = 0; i < a.branches.size(); ++i) {
    EXPECT_EQ(a.branches[i].manifold->pose({}).matrix(), b.branches[i].manifold->pose({}).matrix());
    EXPECT_EQ(a.branches[i].certified.radius, b.branches[i].certified.radius);
  }
}

// Coordinates beyond 1e100 (found by the mutation campaign: a plane distance of 3e154): the poses'
// squared distances would overflow, so the stage declines, as the rules do.
TEST(Stage, DeclinesHugeCoordinates) {
  std::mt19937_64 rng(45);
  const Problem p = test::scaledAndMoved(test::sixSix(rng, randomPose(rng)), 1e120,
                                         Vector3d::Zero(), Vector3d::Zero());
  Solution s;
  EXPECT_FALSE(solveComplete(p, builtinRegistry(), toleranceOf(p), s));
  EXPECT_NE(s.message.find("beyond 1e100"), std::string::npos) << s.message;
  EXPECT_TRUE(s.branches.empty());
}

TEST(Stage, DeclinesWithAReason) {
  std::mt19937_64 rng(37);
  Problem p = test::sixSix(rng, randomPose(rng));
  p.constraints.pop_back();
  Solution s;
  EXPECT_FALSE(solveComplete(p, builtinRegistry(), toleranceOf(p), s));
  EXPECT_NE(s.message.find("5 equations"), std::string::npos) << s.message;
  EXPECT_EQ(s.status, Status::kNotSolved);
}

}  // namespace
}  // namespace relpos::complete
