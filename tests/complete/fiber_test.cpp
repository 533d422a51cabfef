// solveFiber on targets built around known roots: every certified box holds one root, the boxes
// are disjoint, complete exactly when every root is found and none is singular or at infinity.
#include "relpos/complete/fiber.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#include "test_families.hpp"

namespace relpos::complete {
namespace {

using testing::conicPoint;
using testing::twoConics;

bool inBox(const CertifiedRoot& r, const Eigen::VectorXcd& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (std::abs(r.x[i].real() - x[i].real()) > r.radius ||
        std::abs(r.x[i].imag() - x[i].imag()) > r.radius)
      return false;
  return true;
}

int boxesHolding(const FiberResult& res, const Eigen::VectorXcd& x) {
  int n = 0;
  for (const auto& r : res.roots) n += inBox(r, x) ? 1 : 0;
  return n;
}

void expectDisjoint(const FiberResult& res) {
  for (std::size_t i = 0; i < res.roots.size(); ++i) {
    const auto& a = res.roots[i];
    EXPECT_TRUE(a.x.allFinite());
    EXPECT_GT(a.radius, 0.0);
    for (std::size_t j = 0; j < i; ++j) {
      const auto& b = res.roots[j];
      bool apart = false;
      for (Eigen::Index k = 0; k < a.x.size(); ++k)
        apart = apart || std::abs(a.x[k].real() - b.x[k].real()) > a.radius + b.radius ||
                std::abs(a.x[k].imag() - b.x[k].imag()) > a.radius + b.radius;
      EXPECT_TRUE(apart) << "boxes " << i << " and " << j << " overlap";
    }
  }
}

void expectSame(const FiberResult& a, const FiberResult& b) {
  ASSERT_EQ(a.roots.size(), b.roots.size());
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.attempts, b.attempts);
  for (std::size_t i = 0; i < a.roots.size(); ++i) {
    EXPECT_EQ(a.roots[i].x, b.roots[i].x);
    EXPECT_EQ(a.roots[i].radius, b.roots[i].radius);
    EXPECT_EQ(a.roots[i].real, b.roots[i].real);
  }
}

const testing::StewartFamily kStewart;

// Two random real conics through (0.75, -1.25): generic, four finite roots.
TEST(SolveFiber, GenericConicsAreCompleteAndHoldTheKnownRoot) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const double x = 0.75, y = -1.25;
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<double> p(12);
    for (int k = 0; k < 2; ++k) {
      double s = 0.0;
      const double m[5] = {x * x, x * y, y * y, x, y};
      for (int i = 0; i < 5; ++i) s += (p[6 * k + i] = u(rng)) * m[i];
      p[6 * k + 5] = -s;  // exact enough: x, y and the products are dyadic
    }
    const FiberResult res = solveFiber(twoConics(), p);
    EXPECT_EQ(res.root_count, 4);
    EXPECT_TRUE(res.complete) << "trial " << trial;
    EXPECT_EQ(res.roots.size(), 4u);
    EXPECT_EQ(boxesHolding(res, conicPoint(x, y)), 1) << "trial " << trial;
    expectDisjoint(res);
    ASSERT_FALSE(res.roots.empty());
    EXPECT_TRUE(res.roots.front().real);  // real roots sort first
  }
}

// Two circles: (1/2, ±√15/2) and two roots at the circular points at infinity.
TEST(SolveFiber, RootsAtInfinityLeaveTheListIncomplete) {
  const FiberResult res = solveFiber(twoConics(), {1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, -3});
  EXPECT_FALSE(res.complete);
  ASSERT_EQ(res.roots.size(), 2u);
  const double y = std::sqrt(15.0) / 2;
  EXPECT_EQ(boxesHolding(res, conicPoint(0.5, y)), 1);
  EXPECT_EQ(boxesHolding(res, conicPoint(0.5, -y)), 1);
  EXPECT_TRUE(res.roots[0].real && res.roots[1].real);
  // The two missing paths tracked again, carefully, went to infinity again: no third attempt
  // (another γ sends them there too).
  EXPECT_EQ(res.attempts, 2);
  expectDisjoint(res);
}

// x² + 4y² = 4 and (x − 3)² + y² = 1: a double root at (2, 0) and (6, ±i√8).
TEST(SolveFiber, ADoubleRootIsNeverCertifiedNorComplete) {
  const FiberResult res = solveFiber(twoConics(), {1, 0, 4, 0, 0, -4, 1, 0, 1, -6, 0, 8});
  EXPECT_FALSE(res.complete);
  EXPECT_EQ(boxesHolding(res, conicPoint(2.0, 0.0)), 0);
  EXPECT_EQ(boxesHolding(res, conicPoint(6.0, Complex(0, std::sqrt(8.0)))), 1);
  EXPECT_EQ(boxesHolding(res, conicPoint(6.0, Complex(0, -std::sqrt(8.0)))), 1);
  EXPECT_EQ(res.roots.size(), 2u);
  for (const auto& r : res.roots) EXPECT_FALSE(r.real);
  // Split into two simple roots (radius 1 − 1e-4): all four, complete.
  const double r2 = (1.0 - 1e-4) * (1.0 - 1e-4);
  const FiberResult split = solveFiber(twoConics(), {1, 0, 4, 0, 0, -4, 1, 0, 1, -6, 0, 9 - r2});
  EXPECT_TRUE(split.complete);
  EXPECT_EQ(split.roots.size(), 4u);
  expectDisjoint(split);
}

TEST(SolveFiber, RejectsATargetOfTheWrongSizeOrNotFinite) {
  EXPECT_FALSE(solveFiber(twoConics(), {1, 2, 3}).complete);
  EXPECT_TRUE(solveFiber(twoConics(), {1, 2, 3}).roots.empty());
  std::vector<double> p(12, 1.0);
  p[3] = std::nan("");
  EXPECT_FALSE(solveFiber(twoConics(), p).complete);
}

// A 6-6 platform with the pose e = (1, 1, 1, 1)/2 (120° about (1, 1, 1)), g ⊥ e, and dyadic
// anchors: every parameter is exact in double, so the pose is an exact root of the target.
std::vector<double> exactStewartTarget(testing::StewartPose& pose) {
  pose.e = {0.5, 0.5, 0.5, 0.5};
  pose.g = {0.25, -0.75, 0.125, 0.375};  // Σ g = 0: e·g = 0
  std::array<std::array<double, 3>, 6> a{}, b{};
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> u(-16, 16);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = u(rng) / 8.0;
      b[i][j] = u(rng) / 8.0;
    }
  return testing::stewartMemberAround(pose, a, b, {0.75, 0.5, 1.0, -0.25});  // c·e = 1
}

Eigen::VectorXcd poseVector(const testing::StewartPose& pose) {
  Eigen::VectorXcd x(8);
  for (int k = 0; k < 4; ++k) {
    x[k] = pose.e[k];
    x[4 + k] = pose.g[k];
  }
  return x;
}

TEST(SolveFiber, StewartPlatformIsCompleteWithTheKnownPoseCertifiedReal) {
  testing::StewartPose pose;
  const std::vector<double> target = exactStewartTarget(pose);
  const auto t0 = std::chrono::steady_clock::now();
  const FiberResult res = solveFiber(kStewart, target);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::printf("solveFiber(Stewart 6-6): %.2f ms (first call includes nothing but the fiber)\n", ms);
  EXPECT_EQ(res.root_count, 40);
  EXPECT_TRUE(res.complete);
  EXPECT_EQ(res.roots.size(), 40u);
  expectDisjoint(res);
  const Eigen::VectorXcd x = poseVector(pose);
  ASSERT_EQ(boxesHolding(res, x), 1);
  for (const auto& r : res.roots) {
    if (inBox(r, x)) {
      EXPECT_TRUE(r.real);
    }
  }
  // A real root's conjugate is itself; a complex root's conjugate is a root too: in the list.
  for (const auto& r : res.roots) {
    if (!r.real) {
      EXPECT_EQ(boxesHolding(res, r.x.conjugate()), 1);
    }
  }
}

// A general pose (rotation and translation not dyadic): the known pose is within rounding of a
// certified root.
TEST(SolveFiber, StewartPlatformWithAGeneralPose) {
  for (int trial = 0; trial < 3; ++trial) {
    testing::StewartPose pose;
    const auto target = testing::randomStewartMember(23 + trial, pose);
    const FiberResult res = solveFiber(kStewart, target);
    EXPECT_TRUE(res.complete) << "trial " << trial;
    expectDisjoint(res);
    const Eigen::VectorXcd x = poseVector(pose);
    int near = 0;
    for (const auto& r : res.roots)
      if (r.real && (r.x - x).cwiseAbs().maxCoeff() < 1e-8) ++near;
    EXPECT_EQ(near, 1) << "trial " << trial;
  }
}

TEST(SolveFiber, SameOutputOnEveryRunAndThread) {
  testing::StewartPose pose;
  const std::vector<double> target = exactStewartTarget(pose);
  const FiberResult first = solveFiber(kStewart, target);
  expectSame(first, solveFiber(kStewart, target));
  FiberResult a, b;
  std::thread ta([&] { a = solveFiber(kStewart, target); });
  std::thread tb([&] { b = solveFiber(kStewart, target); });
  ta.join();
  tb.join();
  expectSame(first, a);
  expectSame(first, b);
  FiberOptions parallel;
  parallel.threads = 3;
  expectSame(first, solveFiber(kStewart, target, parallel));
  const std::vector<double> circles{1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, -3};
  expectSame(solveFiber(twoConics(), circles), solveFiber(twoConics(), circles, parallel));
  expectSame(solveFiber(twoConics(), circles), solveFiber(twoConics(), circles));
}

// A random real dense system through a known real point: complete, the point in one box.
TEST(SolveFiber, DenseSystemsThroughAKnownPointAreComplete) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const auto& [n, d] : {std::make_pair(3, 2), std::make_pair(2, 3), std::make_pair(4, 2)}) {
    const testing::DenseFamily f(n, d);
    std::vector<Complex> x(n);
    Eigen::VectorXcd known(n);
    for (int i = 0; i < n; ++i) known[i] = x[i] = u(rng) * 0.5 + 0.25 * i;  // not dyadic
    const int per = f.parameterCount() / n;
    std::vector<double> p(f.parameterCount());
    for (int k = 0; k < n; ++k) {
      double s = 0.0;
      for (int j = 0; j + 1 < per; ++j) {
        p[k * per + j] = u(rng);
        s += p[k * per + j] * f.monomialValue(k * per + j, x.data()).real();
      }
      p[k * per + per - 1] = -s;
    }
    const FiberResult res = solveFiber(f, p);
    EXPECT_TRUE(res.complete) << n << " " << d;
    expectDisjoint(res);
    int near = 0;
    for (const auto& r : res.roots)
      if (r.real && (r.x - known).cwiseAbs().maxCoeff() < 1e-10) ++near;
    EXPECT_EQ(near, 1) << n << " " << d;
  }
}

// The platform equal to its base (b_i = a_i) with equal legs: at R = I every translation of
// length d is a pose, a surface of solutions. Its points are singular roots: never certified,
// never "complete".
TEST(SolveFiber, APositiveDimensionalFiberIsNeverComplete) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::array<std::array<double, 3>, 6> a{};
  for (auto& v : a)
    for (auto& w : v) w = u(rng);
  testing::StewartPose pose;
  pose.e = {1.0, 0.0, 0.0, 0.0};
  pose.g = {0.0, 0.3, -0.2, 0.4};  // t = 2g
  const auto target = testing::stewartMemberAround(pose, a, a, {1.0, 0.3, -0.6, 0.2});
  const FiberResult res = solveFiber(kStewart, target);
  EXPECT_FALSE(res.complete);
  EXPECT_LT(res.roots.size(), 40u);
  expectDisjoint(res);
  // No certified box holds a pose of the surface (R = I, |t| = d).
  for (const auto& r : res.roots) {
    const bool identity = std::abs(r.x[1]) + std::abs(r.x[2]) + std::abs(r.x[3]) < 1e-6;
    EXPECT_FALSE(identity);
  }
}

}  // namespace
}  // namespace relpos::complete
