// A Problem as a family member (complete/problem_encoding.hpp): the member vanishes at the true
// pose of problems built around one, in every combination of constraint kinds the encoder takes;
// feature sharing makes its own family; a scaled and moved copy is the same member; what is not
// encoded is refused with a reason.
#include "relpos/complete/problem_encoding.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "family_eval.hpp"
#include "known_problems.hpp"

namespace relpos::complete {
namespace {

using test::evaluateMember;
using test::maxAbs;
using test::randomPose;
using test::randomVector;
using test::realMember;

// The member of p's encoding at the Study parameters of X (in the encoding's frames): of the
// subproblem (an orientation for each 'either' that changes the equations) where it is least.
std::vector<Complex> residualAt(const Problem& p, const Isometry3d& X, PoseEncoding* enc) {
  std::string why;
  EXPECT_TRUE(encodePose(p, 0, enc, &why)) << why;
  std::vector<Complex> best;
  PoseEncoding e;
  for (unsigned alt = 0; alt < (1u << enc->alternatives); ++alt) {
    EXPECT_TRUE(encodePose(p, 0, &e, &why, alt)) << why;
    const PoseFamily f(e.equations, static_cast<int>(e.target.size()));
    const Vector8d x = studyFromPose(e.frames.scaledPose(X), e.chart);
    const std::vector<Complex> r =
        evaluateMember(f, realMember(e.target), {x.data(), x.data() + 8});
    double m = 0.0, mb = 0.0;
    for (const Complex& z : r) m = std::max(m, std::abs(z));
    for (const Complex& z : best) mb = std::max(mb, std::abs(z));
    if (best.empty() || m < mb) best = r, *enc = e;
  }
  return best;
}

TEST(PoseEncoding, TheTruePoseIsARootOfEveryKnownProblem) {
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    for (int k = -2; k < test::kMixedProblems; ++k) {
      const Isometry3d X = randomPose(rng);
      Problem p = k == -2   ? test::sixSix(rng, X)
                  : k == -1 ? test::octahedral(rng, X)
                            : test::mixed(k, rng, X);
      p.fixed.pose = randomPose(rng);  // fixed features are in the fixed frame: placed by it
      // Keep the true pose: re-express the fixed features so that, placed, they are unchanged.
      for (InputConstraint& c : p.constraints) c.fixed = c.fixed.placed(p.fixed.pose.inverse());
      PoseEncoding enc;
      const std::vector<Complex> r = residualAt(p, X, &enc);
      EXPECT_LT(maxAbs(r), 1e-13) << p.name << " trial " << trial;
      for (const SignCheck& s : enc.signs)
        EXPECT_GT(s.sign * s.fixed.dot(X.linear() * s.mobile), 0.5) << p.name;
      // Not at another pose.
      Isometry3d Y = X;
      Y.translation() += 1e-3 * randomVector(rng).normalized();
      Y.linear() = Y.linear() * axisAngle(randomVector(rng).normalized(), 1e-3);
      PoseEncoding enc2;
      EXPECT_GT(maxAbs(residualAt(p, Y, &enc2)), 1e-8) << p.name;
    }
  }
}

TEST(PoseEncoding, EitherThatChangesTheEquationsMakesSubproblems) {
  std::mt19937_64 rng(26);
  const Isometry3d X = randomPose(rng);
  const Problem p = test::mixed(5, rng, X);
  PoseEncoding enc;
  std::string why;
  ASSERT_TRUE(encodePose(p, 0, &enc, &why)) << why;
  EXPECT_EQ(enc.alternatives, 2);
  // The true pose is a root of subproblem "plane-plane opposed, tangency aligned" only (bit 0:
  // the first such constraint opposed).
  for (unsigned alt = 0; alt < 4; ++alt) {
    ASSERT_TRUE(encodePose(p, 0, &enc, &why, alt));
    const PoseFamily f(enc.equations, static_cast<int>(enc.target.size()));
    const Vector8d x = studyFromPose(enc.frames.scaledPose(X), enc.chart);
    const double r = maxAbs(evaluateMember(f, realMember(enc.target), {x.data(), x.data() + 8}));
    if (alt == 1)
      EXPECT_LT(r, 1e-13);
    else
      EXPECT_GT(r, 1e-3) << alt;
  }
}

// An angle of 0 or π (to the rounding of a value converted from degrees) is a parallelism: two
// equations and the orientation checked on the roots, not u·R m = ±1, a double root.
TEST(PoseEncoding, ExtremeAnglesAreParallelisms) {
  std::mt19937_64 rng(28);
  Problem p = test::sixSix(rng, randomPose(rng));
  p.constraints.resize(4);
  p.addFixedFeature("L", Feature::makeLine(Vector3d::Zero(), Vector3d::UnitX()));
  p.addMobileFeature("m", Feature::makeLine(Vector3d::Zero(), Vector3d::UnitY()));
  p.addConstraint("angle", "L", "m", 180.0 * (kPi / 180.0) + 4e-16);
  PoseEncoding enc;
  std::string why;
  ASSERT_TRUE(encodePose(p, 0, &enc, &why)) << why;
  ASSERT_EQ(enc.signs.size(), 1u);
  EXPECT_EQ(enc.signs[0].sign, -1.0);
  int directions = 0;
  for (const PoseEquation& q : enc.equations) {
    if (q.kind != PoseEquationKind::kDirection) continue;
    ++directions;
    EXPECT_EQ(enc.target[q.value], 0.0);  // on two planes through the fixed line
  }
  EXPECT_EQ(directions, 2);
}

// The constraints in another order: the same member of the same family (their canonical order).
TEST(PoseEncoding, PermutedConstraintsAreTheSameMember) {
  std::mt19937_64 rng(29);
  for (int k = 0; k < test::kMixedProblems; ++k) {
    const Problem p = test::mixed(k, rng, randomPose(rng));
    Problem q = p;
    std::reverse(q.constraints.begin(), q.constraints.end());
    PoseEncoding a, b;
    std::string why;
    ASSERT_TRUE(encodePose(p, 0, &a, &why)) << why;
    ASSERT_TRUE(encodePose(q, 0, &b, &why)) << why;
    EXPECT_EQ(a.target, b.target) << p.name;
    EXPECT_EQ(PoseFamily(a.equations, static_cast<int>(a.target.size())).signature(),
              PoseFamily(b.equations, static_cast<int>(b.target.size())).signature());
  }
}

TEST(PoseEncoding, SharedFeaturesMakeTheirOwnFamily) {
  std::mt19937_64 rng(22);
  const Isometry3d X = randomPose(rng);
  PoseEncoding general, octa;
  std::string why;
  ASSERT_TRUE(encodePose(test::sixSix(rng, X), 0, &general, &why)) << why;
  ASSERT_TRUE(encodePose(test::octahedral(rng, X), 0, &octa, &why)) << why;
  // 6-6: chart 4, 6 × (a, b, D); octahedral: chart 4, 3 a, 3 b, 6 D.
  EXPECT_EQ(general.target.size(), 4u + 6u * 7u);
  EXPECT_EQ(octa.target.size(), 4u + 18u + 6u);
  const PoseFamily f(general.equations, static_cast<int>(general.target.size()));
  const PoseFamily g(octa.equations, static_cast<int>(octa.target.size()));
  EXPECT_NE(f.signature(), g.signature());
  // Another 6-6 problem is the same family (one start system for all of them).
  PoseEncoding other;
  ASSERT_TRUE(encodePose(test::sixSix(rng, randomPose(rng)), 0, &other, &why));
  EXPECT_EQ(PoseFamily(other.equations, static_cast<int>(other.target.size())).signature(),
            f.signature());
}

TEST(PoseEncoding, AScaledAndMovedCopyIsTheSameMember) {
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 20; ++trial) {
    const Isometry3d X = randomPose(rng);
    const Problem p = trial % 2 ? test::sixSix(rng, X) : test::mixed(trial % 5, rng, X);
    // Scales from 1e-3 to 1e3 (the input rounding of coordinates 1e3 away, relative to the
    // problem's size, stays below 1e-10).
    const double s = std::pow(10.0, 3.0 * randomVector(rng).x());
    const Vector3d dW = 1e3 * randomVector(rng), dM = 1e2 * randomVector(rng);
    const Problem q = test::scaledAndMoved(p, s, dW, dM);
    PoseEncoding a, b;
    std::string why;
    ASSERT_TRUE(encodePose(p, 1, &a, &why)) << why;
    ASSERT_TRUE(encodePose(q, 1, &b, &why)) << why;
    ASSERT_EQ(a.target.size(), b.target.size());
    for (std::size_t i = 0; i < a.target.size(); ++i)
      EXPECT_NEAR(a.target[i], b.target[i], 1e-9) << p.name << " parameter " << i;
    EXPECT_EQ(PoseFamily(a.equations, static_cast<int>(a.target.size())).signature(),
              PoseFamily(b.equations, static_cast<int>(b.target.size())).signature());
    // The same pose in both frames, mapped.
    const Isometry3d Y = test::movedPose(X, s, dW, dM);
    EXPECT_LT((a.frames.scaledPose(X).matrix() - b.frames.scaledPose(Y).matrix()).norm(), 1e-8);
    EXPECT_LT((b.frames.poseOf(a.frames.scaledPose(X)).matrix() - Y.matrix()).norm(),
              1e-8 * (1.0 + Y.translation().norm()));
  }
}

TEST(PoseEncoding, RefusesWhatItDoesNotEncode) {
  std::mt19937_64 rng(24);
  const Isometry3d X = randomPose(rng);
  PoseEncoding enc;
  std::string why;
  Problem p = test::sixSix(rng, X);
  p.constraints.pop_back();
  EXPECT_FALSE(encodePose(p, 0, &enc, &why));
  EXPECT_NE(why.find("5 equations"), std::string::npos) << why;
  p = test::sixSix(rng, X);
  p.constraints[2].has_value = false, p.constraints[2].min = 0.1, p.constraints[2].max = 0.2;
  EXPECT_FALSE(encodePose(p, 0, &enc, &why));
  EXPECT_NE(why.find("range"), std::string::npos) << why;
  p = test::sixSix(rng, X);
  p.constraints[0].type = "helical";
  EXPECT_FALSE(encodePose(p, 0, &enc, &why));
  EXPECT_NE(why.find("helical"), std::string::npos) << why;
}

TEST(LineEncoding, FourSpheres) {
  std::mt19937_64 rng(25);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector3d w = randomVector(rng).normalized();
    const Vector3d q = randomVector(rng);
    const Problem p = test::fourSpheres(rng, q, w);
    const Tolerance tol = Tolerance::forScale(2.0);
    ASSERT_TRUE(mobileFeaturesOnOneLine(p, tol));
    EXPECT_FALSE(mobileFeaturesOnOneLine(test::sixSix(rng, Isometry3d::Identity()), tol));
    LineEncoding enc;
    std::string why;
    ASSERT_TRUE(encodeLine(p, tol, &enc, &why)) << why;
    const LineFamily f(enc.equations, static_cast<int>(enc.target.size()));
    // The line in the encoding's frame: its foot.
    Vector3d qs = enc.frames.fixedPoint(q);
    qs -= qs.dot(w) * w;
    for (const Vector3d& dir : {w, Vector3d(-w)}) {
      const std::vector<Complex> x = {dir.x(), dir.y(), dir.z(), qs.x(), qs.y(), qs.z()};
      EXPECT_LT(maxAbs(evaluateMember(f, realMember(enc.target), x)), 1e-13);
    }
  }
}

// A cylinder lying in the corner of two planes (tangent to both): its axis, either way along
// the corner, is a root of the line encoding.
TEST(LineEncoding, CylinderInACorner) {
  std::mt19937_64 rng(27);
  Problem p;
  const Vector3d n1 = randomVector(rng).normalized();
  const Vector3d n2 = (n1.cross(randomVector(rng)) + 0.3 * n1).normalized();
  const Vector3d w = n1.cross(n2).normalized();
  const double r = 0.4;
  // The axis: r behind each plane (each normal pointing away from it: aligned).
  const Vector3d corner = randomVector(rng);
  p.addFixedFeature("P1", Feature::makePlane(corner, n1));
  p.addFixedFeature("P2", Feature::makePlane(corner, n2));
  p.addMobileFeature("C", Feature::makeCylinder(Vector3d(0, 0, 0.5), Vector3d::UnitX(), r));
  p.addConstraint("tangent", "P1", "C", 0.0, Orientation::kAligned);
  p.addConstraint("tangent", "P2", "C", 0.0, Orientation::kAligned);
  // A point on the axis: x·n1 = corner·n1 − r, x·n2 = corner·n2 − r.
  Eigen::Matrix3d A;
  A.row(0) = n1, A.row(1) = n2, A.row(2) = w;
  const Vector3d x = A.inverse() * Vector3d(corner.dot(n1) - r, corner.dot(n2) - r, 0.0);
  LineEncoding enc;
  std::string why;
  ASSERT_TRUE(encodeLine(p, Tolerance::forScale(2.0), &enc, &why)) << why;
  const LineFamily f(enc.equations, static_cast<int>(enc.target.size()));
  Vector3d qs = enc.frames.fixedPoint(x);
  qs -= qs.dot(w) * w;
  for (const Vector3d& dir : {w, Vector3d(-w)}) {
    const std::vector<Complex> y = {dir.x(), dir.y(), dir.z(), qs.x(), qs.y(), qs.z()};
    EXPECT_LT(maxAbs(evaluateMember(f, realMember(enc.target), y)), 1e-13);
  }
}

}  // namespace
}  // namespace relpos::complete
