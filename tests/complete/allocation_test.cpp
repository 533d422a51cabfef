// Tracking a path and certifying its endpoint allocate nothing (the engine's hot loop: fixed-max
// Eigen types, scratch sized once per tracker and certifier). Counts every global operator new;
// its own executable so the replacement does not affect the other suites.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "chart.hpp"
#include "homotopy.hpp"
#include "krawczyk.hpp"
#include "random.hpp"
#include "relpos/complete/fiber.hpp"
#include "test_families.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace relpos::complete {
namespace {

TEST(CompleteAllocation, CounterSeesAllocations) {
  const long before = g_allocations.load();
  auto* v = new std::vector<int>(100);
  delete v;
  EXPECT_GE(g_allocations.load() - before, 2);
}

TEST(CompleteAllocation, TrackingAndCertifyingStewartPathsAllocateNothing) {
  const testing::StewartFamily f;
  const StartSystem& s = startSystem(f);
  ASSERT_FALSE(s.roots.empty());
  testing::StewartPose pose;
  pose.e = {0.5, 0.5, 0.5, 0.5};
  pose.g = {0.25, -0.75, 0.125, 0.375};
  std::array<std::array<double, 3>, 6> a{}, b{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 3; ++j) {
      a[i][j] = ((i * 7 + j * 3) % 11 - 5) / 4.0;
      b[i][j] = ((i * 5 + j * 2) % 7 - 3) / 4.0;
    }
  const auto t = testing::stewartMemberAround(pose, a, b, {0.75, 0.5, 1.0, -0.25});
  const detail::CompiledShape shape(f.shape());
  std::vector<Complex> p1(t.begin(), t.end()), c1(shape.terms());
  f.coefficients(p1.data(), c1.data());
  std::vector<Interval> ip(t.begin(), t.end()), ic(shape.terms());
  f.coefficients(ip.data(), ic.data());
  const auto poly = detail::interpolateSegment(f, s.params.data(), p1.data());
  detail::Tracker tracker(shape, poly, detail::Arc{detail::randomGamma(7)}, c1.data());
  detail::Certifier certifier(shape, ic.data());
  std::vector<detail::CVec> starts(s.roots.begin(), s.roots.end());
  int certified = 0;
  const long before = g_allocations.load();
  for (const auto& x : starts) {
    const detail::PathEnd e = tracker.track(x);
    if (e.status == detail::PathStatus::kFinite) certified += certifier.certify(e.x).ok ? 1 : 0;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_GT(certified, 0);
}

// A chart's pose (Newton's method on the slice) and its projection, what every sample and
// nearest-pose query of a chart branch runs, allocate nothing (docs/spec.md §8.7): a point at
// distance 0.5 from a fixed point and on a plane z = 0.1 (2 equations, a 4-DOF set).
TEST(CompleteAllocation, AChartsPoseAndProjectionAllocateNothing) {
  using detail::Condition;
  using detail::ConditionKind;
  detail::ConditionSystem system;
  Condition sphere;
  sphere.kind = ConditionKind::kPointPoint;
  sphere.p = {0.2, 0.0, 0.0};
  sphere.lo = sphere.hi = 0.25;
  Condition plane;
  plane.kind = ConditionKind::kPointPlane;
  plane.p = {0.2, 0.0, 0.0};
  plane.q = {0.0, 0.0, 0.1};
  plane.d = {0.0, 0.0, 1.0};
  system.equations = {sphere, plane};
  // the base: the point at (0.2, 0, 0) + t on the plane, 0.5 from the origin
  const Vector3d t0(-0.2 + std::sqrt(0.25 - 0.01), 0.0, 0.1);
  detail::Chart chart;
  ASSERT_TRUE(detail::makeChart(system, Matrix3d::Identity(), t0, &chart));
  ASSERT_TRUE(detail::growChart(chart, 1e-3, 4.0));
  ASSERT_EQ(chart.d, 4);
  Matrix3d R;
  Vector3d t;
  const long before = g_allocations.load();
  for (int k = 0; k < 10; ++k) {
    std::array<double, 6> theta{};
    for (int j = 0; j < chart.d; ++j) theta[j] = chart.radius[j] * (0.1 * k - 0.45);
    detail::chartPose(chart, theta, &R, &t);
    const std::array<double, 6> back = detail::chartProject(chart, R, t);
    (void)back;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  // and the pose found is on the set
  EXPECT_NEAR((R * Vector3d(0.2, 0, 0) + t).norm(), 0.5, 1e-12);
  EXPECT_NEAR((R * Vector3d(0.2, 0, 0) + t).z(), 0.1, 1e-12);
}

}  // namespace
}  // namespace relpos::complete
