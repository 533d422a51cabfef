// The coefficient interpolation and the tracker on homotopies whose paths are known.
#include "homotopy.hpp"

#include <gtest/gtest.h>

#include <random>
#include <utility>

#include "test_families.hpp"

namespace relpos::complete {
namespace {

// The interpolated coefficients equal Family::coefficients along the segment, also at complex τ
// off [0, 1] (the γ arc leaves the segment).
TEST(Homotopy, InterpolationReproducesTheCoefficientsOnTheWholeLine) {
  const testing::StewartFamily f;
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g;
  std::vector<Complex> p0(46), p1(46), p(46);
  for (auto& v : p0) v = {g(rng), g(rng)};
  for (auto& v : p1) v = g(rng);
  const auto poly = detail::interpolateSegment(f, p0.data(), p1.data());
  EXPECT_EQ(poly.degree, 2);
  const int terms = static_cast<int>(f.shape().terms.size());
  std::vector<Complex> c(terms), want(terms);
  for (const Complex tau : {Complex(0.0), Complex(1.0), Complex(0.3, 0.7), Complex(-1.5, 2.0)}) {
    for (int i = 0; i < 46; ++i) p[i] = p0[i] + tau * (p1[i] - p0[i]);
    f.coefficients(p.data(), want.data());
    poly.evaluate(tau, c.data(), nullptr);
    for (int t = 0; t < terms; ++t)
      EXPECT_LT(std::abs(c[t] - want[t]), 1e-12 * (1 + std::abs(want[t]))) << "term " << t;
  }
}

TEST(Homotopy, TheArcRunsFromZeroToOne) {
  const detail::Arc arc{detail::randomGamma(5)};
  EXPECT_NEAR(std::abs(arc.gamma), 1.0, 1e-15);
  EXPECT_LT(std::abs(arc.tau(0.0)), 1e-15);
  EXPECT_LT(std::abs(arc.tau(1.0) - 1.0), 1e-15);
  const double h = 1e-6;
  const Complex d = (arc.tau(0.4 + h) - arc.tau(0.4 - h)) / (2 * h);
  EXPECT_LT(std::abs(d - arc.dtau(0.4)), 1e-8);
  EXPECT_NE(detail::randomGamma(5), detail::randomGamma(6));
}

// One equation in one unknown: a x^degree + b, a and b linear in τ (a0, a1, b0, b1).
struct OneVariable {
  SystemShape shape;
  detail::CoefficientPolynomials poly;
  OneVariable(int degree, std::vector<Complex> a) {
    shape.variables = 1;
    Monomial m;
    m.degree = static_cast<std::uint8_t>(degree);
    shape.monomials = {m, Monomial{}};
    shape.terms = {{0, 0}, {0, 1}};
    poly.terms = 2;
    poly.degree = 1;
    poly.a = std::move(a);
  }
};

// x² = 1 + 3τ along the arc: from x = ±1 to ±2, each path to its own root.
TEST(Homotopy, TracksSquareRootsToTheirEnds) {
  const OneVariable sys(2, {1.0, 0.0, -1.0, -3.0});  // 1 · x² + (−1 − 3τ)
  const detail::CompiledShape shape(sys.shape);
  const Complex end[2] = {1.0, -4.0};
  detail::Tracker tracker(shape, sys.poly, detail::Arc{detail::randomGamma(3)}, end);
  for (const double x0 : {1.0, -1.0}) {
    detail::CVec start(1);
    start << x0;
    const detail::PathEnd e = tracker.track(start);
    ASSERT_EQ(e.status, detail::PathStatus::kFinite);
    EXPECT_LT(std::abs(e.x[0] - 2.0 * x0), 1e-13);
  }
}

// x (1 − τ) = 1: the root leaves to infinity as τ → 1.
TEST(Homotopy, ClassifiesADivergingPathAsAtInfinity) {
  const OneVariable sys(1, {1.0, -1.0, -1.0, 0.0});  // (1 − τ) x − 1
  const detail::CompiledShape shape(sys.shape);
  detail::Tracker tracker(shape, sys.poly, detail::Arc{detail::randomGamma(3)}, nullptr);
  detail::CVec start(1);
  start << 1.0;
  EXPECT_EQ(tracker.track(start).status, detail::PathStatus::kAtInfinity);
}

}  // namespace
}  // namespace relpos::complete
