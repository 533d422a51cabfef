// The Krawczyk certifier on conics whose roots are known in closed form.
#include "krawczyk.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_families.hpp"

namespace relpos::complete {
namespace {

using detail::BoxCertificate;
using detail::Certifier;
using detail::CompiledShape;
using detail::CVec;
using testing::conicPoint;
using testing::twoConics;

// Conic coefficients (x², xy, y², x, y, 1) of two conics, as degenerate intervals.
std::vector<Interval> conics(const std::array<double, 12>& p) {
  return std::vector<Interval>(p.begin(), p.end());
}

bool contains(const BoxCertificate& c, Complex x, Complex y) {
  const CVec k = conicPoint(x, y);
  for (int i = 0; i < 2; ++i)
    if (std::abs(c.x[i].real() - k[i].real()) > c.radius ||
        std::abs(c.x[i].imag() - k[i].imag()) > c.radius)
      return false;
  return true;
}

// x² + y² = 4 and (x − 1)² + y² = 4 meet at (1/2, ±√15/2).
TEST(Krawczyk, CertifiesARealRootInABoxHoldingIt) {
  const CompiledShape shape(twoConics().shape());
  const auto c = conics({1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, -3});
  Certifier cert(shape, c.data());
  const double y = std::sqrt(15.0) / 2;
  const BoxCertificate b = cert.certify(conicPoint({0.5 + 1e-9, 1e-10}, {y - 1e-9, -1e-10}));
  ASSERT_TRUE(b.ok);
  EXPECT_TRUE(b.real);
  EXPECT_GT(b.radius, 0.0);
  EXPECT_LT(b.radius, 1e-3);
  EXPECT_TRUE(contains(b, 0.5, y));
  EXPECT_FALSE(contains(b, 0.5, -y));
}

TEST(Krawczyk, FailsOnABoxWithoutARoot) {
  const CompiledShape shape(twoConics().shape());
  const auto c = conics({1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, -3});
  Certifier cert(shape, c.data());
  EXPECT_FALSE(cert.testComplex(conicPoint(0.5, 1.0), 1e-3));
  EXPECT_FALSE(cert.testComplex(conicPoint(0.5, 1.0), 0.1));
  EXPECT_FALSE(cert.certify(conicPoint({3.0, 1.0}, {2.0, -1.0})).ok);
}

// x² + 4y² = 4 and (x − 3)² + y² = 1: tangent at (2, 0) (a double root), and (6, ±i√8).
TEST(Krawczyk, NeverCertifiesADoubleRootAndProvesComplexRootsNonReal) {
  const CompiledShape shape(twoConics().shape());
  const auto c = conics({1, 0, 4, 0, 0, -4, 1, 0, 1, -6, 0, 8});
  Certifier cert(shape, c.data());
  EXPECT_FALSE(cert.certify(conicPoint(2.0, 0.0)).ok);
  EXPECT_FALSE(cert.certify(conicPoint(2.0 + 1e-8, 1e-8)).ok);
  for (double r = 1e-12; r < 1.0; r *= 10) EXPECT_FALSE(cert.testComplex(conicPoint(2.0, 0.0), r));
  const BoxCertificate b = cert.certify(conicPoint(6.0, Complex(0.0, std::sqrt(8.0))));
  ASSERT_TRUE(b.ok);
  EXPECT_FALSE(b.real);
  EXPECT_TRUE(contains(b, 6.0, Complex(0.0, std::sqrt(8.0))));
}

// The box's proof covers the coefficients' rounding: a member whose coefficients are wide
// intervals (±1e-3) is certified only with a box wide enough for all of its members.
TEST(Krawczyk, WideCoefficientsNeedAWideBox) {
  const CompiledShape shape(twoConics().shape());
  std::vector<Interval> c = conics({1, 0, 1, 0, 0, -4, 1, 0, 1, -2, 0, -3});
  c[5] = Interval(-4.001, -3.999);
  Certifier cert(shape, c.data());
  const BoxCertificate b = cert.certify(conicPoint(0.5, std::sqrt(15.0) / 2));
  ASSERT_TRUE(b.ok);
  EXPECT_GE(b.radius, 1e-4);  // x² + y² = 4 ± 0.001 moves y by up to ~1.3e-4
}

TEST(Krawczyk, BoxesOverlapOnlyWhenEveryPartIsWithinReach) {
  const CVec a = conicPoint({1.0, 0.0}, {2.0, 0.0});
  EXPECT_TRUE(detail::boxesOverlap(a, 1e-3, conicPoint({1.0015, 0.0}, {2.0, 0.0015}), 1e-3));
  EXPECT_FALSE(detail::boxesOverlap(a, 1e-3, conicPoint({1.003, 0.0}, {2.0, 0.0}), 1e-3));
  EXPECT_FALSE(detail::boxesOverlap(a, 1e-3, conicPoint({1.0, 0.0}, {2.0, 0.003}), 1e-3));
}

}  // namespace
}  // namespace relpos::complete
