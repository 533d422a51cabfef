// The pose and line encodings (complete/encoding.hpp): each equation vanishes at the Study
// parameters of the true pose of random real problems and not at a perturbed pose; the interval
// coefficients enclose the double ones; seedMember's root is a root of its member.
#include "relpos/complete/encoding.hpp"

#include <gtest/gtest.h>

#include <random>

#include "family_eval.hpp"
#include "known_problems.hpp"
#include "relpos/complete/study.hpp"

namespace relpos::complete {
namespace {

using test::evaluateMember;
using test::maxAbs;
using test::randomPose;
using test::randomVector;
using test::realMember;
using K = PoseEquationKind;

// A real member with one equation of every kind, its parameters read off the pose X (so X is a
// root), with a shared mobile point (in kPointPoint and kPointPlane) and a shared fixed line.
struct RealMember {
  std::vector<PoseEquation> eqs;
  std::vector<double> params;
  Eigen::Vector4d chart;
};

RealMember memberOf(const Isometry3d& X, std::mt19937_64& rng) {
  RealMember m;
  auto slot = [&](const Vector3d& v) {
    const int at = static_cast<int>(m.params.size());
    for (int i = 0; i < 3; ++i) m.params.push_back(v[i]);
    return at;
  };
  auto value = [&](double v) {
    m.params.push_back(v);
    return static_cast<int>(m.params.size()) - 1;
  };
  const Matrix3d& R = X.linear();
  const Vector3d& t = X.translation();
  m.chart = Eigen::Vector4d(0.9, 1.1, 0.7, 1.3);
  PoseEquation chart{K::kChart, -1, -1, -1, -1};
  chart.value = static_cast<int>(m.params.size());
  for (int i = 0; i < 4; ++i) m.params.push_back(m.chart[i]);
  m.eqs.push_back(chart);
  m.eqs.push_back({K::kStudy, -1, -1, -1, -1});
  const Vector3d a = randomVector(rng), b = randomVector(rng);
  const int sa = slot(a), sb = slot(b);
  m.eqs.push_back({K::kPointPoint, sa, sb, -1, value((R * b + t - a).squaredNorm())});
  const Vector3d n = randomVector(rng);
  m.eqs.push_back({K::kPointPlane, slot(n), sb, -1, value(n.dot(R * b + t))});
  const Vector3d a2 = randomVector(rng), mm = randomVector(rng);
  m.eqs.push_back(
      {K::kPlanePoint, slot(a2), slot(mm), -1, value(mm.dot(R.transpose() * (a2 - t)))});
  const Vector3d la = randomVector(rng), lu = randomVector(rng), b2 = randomVector(rng);
  const int sla = slot(la), slu = slot(lu);
  m.eqs.push_back({K::kPointLine, sla, slot(b2), slu,
                   value((R * b2 + t - la).cross(lu).squaredNorm() / lu.squaredNorm())});
  const Vector3d lb = randomVector(rng), lm = randomVector(rng);
  const Vector3d aM = R.transpose() * (la - t);  // the shared fixed line's point, mobile frame
  const int slm = slot(lm);
  m.eqs.push_back({K::kLinePoint, sla, slot(lb), slm,
                   value((aM - lb).cross(lm).squaredNorm() / lm.squaredNorm())});
  m.eqs.push_back({K::kDirection, slu, slm, -1, value(lu.dot(R * lm))});
  return m;
}

std::vector<Complex> asComplex(const Vector8d& x) { return {x.data(), x.data() + 8}; }

TEST(PoseFamily, EveryEquationVanishesAtTheTruePoseAndNotNearIt) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Isometry3d X = randomPose(rng);
    const RealMember m = memberOf(X, rng);
    const PoseFamily f(m.eqs, static_cast<int>(m.params.size()));
    const Vector8d x = studyFromPose(X, m.chart);
    const std::vector<Complex> r = evaluateMember(f, realMember(m.params), asComplex(x));
    EXPECT_LT(maxAbs(r), 1e-14) << "trial " << trial;
    // A pose turned by 1e-3 rad and moved 1e-3 breaks every equation but the chart and the
    // Study quadric (which hold for any pose).
    Isometry3d Y = X;
    Y.linear() = X.linear() * axisAngle(randomVector(rng).normalized(), 1e-3);
    Y.translation() += 1e-3 * randomVector(rng).normalized();
    const std::vector<Complex> ry =
        evaluateMember(f, realMember(m.params), asComplex(studyFromPose(Y, m.chart)));
    EXPECT_LT(std::abs(ry[0]), 1e-14);
    EXPECT_LT(std::abs(ry[1]), 1e-14);
    for (int k = 2; k < 8; ++k)
      EXPECT_GT(std::abs(ry[k]), 1e-7) << "trial " << trial << " eq " << k;
  }
}

TEST(PoseFamily, IntervalCoefficientsEncloseTheDoubleOnes) {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const RealMember m = memberOf(randomPose(rng), rng);
    const PoseFamily f(m.eqs, static_cast<int>(m.params.size()));
    const std::size_t n = f.shape().terms.size();
    std::vector<Complex> c(n);
    f.coefficients(realMember(m.params).data(), c.data());
    std::vector<Interval> p(m.params.begin(), m.params.end()), ci(n);
    f.coefficients(p.data(), ci.data());
    for (std::size_t t = 0; t < n; ++t) {
      const double slack = 1e-14 * (1.0 + std::abs(c[t]));
      EXPECT_LE(ci[t].lower(), c[t].real() + slack);
      EXPECT_GE(ci[t].upper(), c[t].real() - slack);
      EXPECT_LT(width(ci[t]), 1e-12 * (1.0 + std::abs(c[t])));  // tight, not [-inf, inf]
      EXPECT_EQ(c[t].imag(), 0.0);
    }
  }
}

TEST(PoseFamily, SeedMembersRootSatisfiesItsMember) {
  std::mt19937_64 rng(13);
  const RealMember m = memberOf(randomPose(rng), rng);
  const PoseFamily f(m.eqs, static_cast<int>(m.params.size()));
  for (std::uint64_t seed = 1; seed < 20; ++seed) {
    std::vector<Complex> p(static_cast<std::size_t>(f.parameterCount())), x(8);
    f.seedMember(seed, p.data(), x.data());
    EXPECT_LT(maxAbs(evaluateMember(f, p, x)), 1e-14);
    EXPECT_GT(std::abs(x[4]), 0.0);  // a complex member, not a degenerate one
    EXPECT_GT(std::abs(p[f.poseEquations()[2].value].imag()), 0.0);
    std::vector<Complex> q(p.size()), y(8);
    f.seedMember(seed, q.data(), y.data());
    EXPECT_EQ(p, q);  // deterministic
    EXPECT_EQ(x, y);
  }
}

TEST(PoseFamily, ShapeAndDegrees) {
  std::mt19937_64 rng(14);
  const RealMember m = memberOf(randomPose(rng), rng);
  const PoseFamily f(m.eqs, static_cast<int>(m.params.size()));
  EXPECT_EQ(f.shape().variables, 8);
  EXPECT_EQ(f.coefficientDegree(), 4);  // the point-line equations: |u|² (v·v): u² b² …
  int max_degree = 0;
  for (const Monomial& mo : f.shape().monomials) max_degree = std::max<int>(max_degree, mo.degree);
  EXPECT_EQ(max_degree, 4);
  // Sharing is in the signature: the same kinds on unshared features make another family.
  std::vector<PoseEquation> unshared = m.eqs;
  std::vector<double> params = m.params;
  unshared[3].mobile = static_cast<int>(params.size());
  for (double v : {0.1, 0.2, 0.3}) params.push_back(v);
  const PoseFamily g(unshared, static_cast<int>(params.size()));
  EXPECT_NE(f.signature(), g.signature());
}

TEST(PoseFamily, RefusesASharedValueParameter) {
  std::vector<PoseEquation> eqs = {{K::kChart, -1, -1, -1, 0}, {K::kStudy, -1, -1, -1, -1}};
  for (int i = 0; i < 6; ++i) eqs.push_back({K::kPointPoint, 4, 7, -1, 10});
  EXPECT_THROW(PoseFamily(eqs, 11), std::invalid_argument);
  eqs.pop_back();
  EXPECT_THROW(PoseFamily(eqs, 11), std::invalid_argument);  // 7 equations
}

TEST(Study, PoseRoundTrip) {
  std::mt19937_64 rng(15);
  const Eigen::Vector4d chart(0.3, -1.2, 0.8, 0.5);
  for (int trial = 0; trial < 100; ++trial) {
    const Isometry3d X = randomPose(rng);
    const Vector8d x = studyFromPose(X, chart);
    EXPECT_NEAR(chart.dot(x.head<4>()), 1.0, 1e-12);
    EXPECT_NEAR(x.head<4>().dot(x.tail<4>()), 0.0, 1e-12);
    const Isometry3d Y = poseFromStudy(x);
    EXPECT_LT((Y.matrix() - X.matrix()).norm(), 1e-12);
    // Any nonzero multiple of e (with g) is the same pose.
    const Isometry3d Z = poseFromStudy(-3.5 * x);
    EXPECT_LT((Z.matrix() - X.matrix()).norm(), 1e-12);
  }
}

TEST(Study, EnclosureHoldsThePosesOfTheBox) {
  std::mt19937_64 rng(16);
  Normalisation n;
  n.centre_W = Vector3d(3, -2, 1), n.centre_M = Vector3d(-1, 0.5, 2), n.scale = 7.0;
  for (int trial = 0; trial < 30; ++trial) {
    const Isometry3d X = randomPose(rng);
    const Vector8d x = studyFromPose(X, Eigen::Vector4d(1, 1, 1, 1));
    const double r = 1e-6;
    PoseEnclosure enc;
    ASSERT_TRUE(enclosePose(x, r, n, &enc));
    EXPECT_LT((enc.pose.matrix() - n.poseOf(X).matrix()).norm(), 1e-9);
    EXPECT_GT(enc.radius, 0.0);
    EXPECT_LT(enc.radius, 1e-3);
    // Corners of the box: their poses lie within the bounds.
    for (int corner = 0; corner < 16; ++corner) {
      Vector8d y = x;
      for (int i = 0; i < 8; ++i) y[i] += ((corner >> (i % 4)) & 1 ? r : -r) * (i < 4 ? 1 : -1);
      const Isometry3d Y = n.poseOf(poseFromStudy(y));
      EXPECT_LE((Y.translation() - enc.pose.translation()).cwiseAbs().maxCoeff(), enc.radius);
      EXPECT_LE(rotationDistance(Y.linear(), enc.pose.linear()), enc.angle);
    }
  }
}

TEST(Study, NormalisationMapsPosesBack) {
  std::mt19937_64 rng(17);
  Normalisation n;
  n.centre_W = Vector3d(10, 0, -4), n.centre_M = Vector3d(0.5, 0.5, 9), n.scale = 0.01;
  for (int trial = 0; trial < 20; ++trial) {
    const Isometry3d X = randomPose(rng);
    const Vector3d b = randomVector(rng);
    // The scaled pose maps the scaled mobile point to the scaled image.
    const Isometry3d S = n.scaledPose(X);
    EXPECT_LT((S * n.mobilePoint(b) - n.fixedPoint(X * b)).norm(), 1e-9);
    EXPECT_LT((n.poseOf(S).matrix() - X.matrix()).norm(), 1e-9);
  }
}

// The line encoding at a true line: random fixed points at the line's distances, a fixed
// direction's angle, a plane the line lies in at an offset.
TEST(LineFamily, EveryEquationVanishesAtTheTrueLineAndNotNearIt) {
  std::mt19937_64 rng(18);
  using L = LineEquationKind;
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3d w = randomVector(rng).normalized();
    Vector3d q = randomVector(rng);
    q -= q.dot(w) * w;
    std::vector<double> params;
    auto slot = [&](const Vector3d& v) {
      for (int i = 0; i < 3; ++i) params.push_back(v[i]);
      return static_cast<int>(params.size()) - 3;
    };
    auto value = [&](double v) {
      params.push_back(v);
      return static_cast<int>(params.size()) - 1;
    };
    std::vector<LineEquation> eqs = {{L::kUnit, -1, -1}, {L::kFoot, -1, -1}};
    for (int i = 0; i < 2; ++i) {
      const Vector3d p = randomVector(rng);
      const int s = slot(p);
      eqs.push_back({L::kPointDistance, s, value((p - q).cross(w).squaredNorm())});
    }
    const Vector3d u = randomVector(rng);
    const int su = slot(u);
    eqs.push_back({L::kDirection, su, value(u.dot(w))});
    const Vector3d n = w.cross(randomVector(rng));
    const int sn = slot(n);
    eqs.push_back({L::kPlaneOffset, sn, value(n.dot(q + 0.7 * w))});
    const LineFamily f(eqs, static_cast<int>(params.size()));
    std::vector<Complex> x = {w.x(), w.y(), w.z(), q.x(), q.y(), q.z()};
    EXPECT_LT(maxAbs(evaluateMember(f, realMember(params), x)), 1e-14);
    const Vector3d w2 = (w + 1e-3 * randomVector(rng)).normalized();
    Vector3d q2 = q + 1e-3 * randomVector(rng);
    q2 -= q2.dot(w2) * w2;
    x = {w2.x(), w2.y(), w2.z(), q2.x(), q2.y(), q2.z()};
    const std::vector<Complex> r = evaluateMember(f, realMember(params), x);
    for (int k = 2; k < 6; ++k) EXPECT_GT(std::abs(r[k]), 1e-7) << "trial " << trial;
    // The seed member of this family.
    std::vector<Complex> p(params.size()), y(6);
    f.seedMember(7, p.data(), y.data());
    EXPECT_LT(maxAbs(evaluateMember(f, p, y)), 1e-14);
    std::vector<Interval> pi(params.begin(), params.end()), ci(f.shape().terms.size());
    std::vector<Complex> c(ci.size());
    f.coefficients(pi.data(), ci.data());
    f.coefficients(realMember(params).data(), c.data());
    for (std::size_t t = 0; t < c.size(); ++t) {
      EXPECT_LE(ci[t].lower(), c[t].real() + 1e-14 * (1 + std::abs(c[t])));
      EXPECT_GE(ci[t].upper(), c[t].real() - 1e-14 * (1 + std::abs(c[t])));
    }
  }
}

}  // namespace
}  // namespace relpos::complete
