// The trace test (trace_test.hpp) on the engine's test families: it passes for the complete
// start systems and fails when a root is withheld (a subset of an irreducible curve's witness set
// or fibre never passes).
#include "trace_test.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "relpos/complete/fiber.hpp"
#include "test_families.hpp"

namespace relpos::complete {
namespace {

void expectPasses(const Family& f, int roots) {
  const StartSystem& s = startSystem(f);
  ASSERT_EQ(static_cast<int>(s.roots.size()), roots);
  const detail::TraceOutcome t = detail::traceTest(f, s, 11);
  std::printf("trace test: %d affine parameters, %d witness points, %d loops, residual %.1e\n",
              t.affine_parameters, t.witness_points, t.loops, t.trace_residual);
  EXPECT_TRUE(t.passed) << t.why;
  EXPECT_EQ(t.fibre_roots, roots);
  EXPECT_GE(t.witness_points, 1);
  EXPECT_LE(t.trace_residual, 1e-7);
}

void expectFailsWithoutOneRoot(const Family& f) {
  StartSystem s = startSystem(f);
  s.roots.pop_back();
  const detail::TraceOutcome t = detail::traceTest(f, s, 11);
  EXPECT_FALSE(t.passed);
  EXPECT_FALSE(t.why.empty());
  std::printf("without one root: %s\n", t.why.c_str());
}

TEST(TraceTest, TwoConics) {
  const testing::ConicFamily f;
  expectPasses(f, 4);
  expectFailsWithoutOneRoot(f);
}

TEST(TraceTest, DenseThreeQuadrics) {
  const testing::DenseFamily f(3, 2);
  expectPasses(f, 8);
  expectFailsWithoutOneRoot(f);
}

TEST(TraceTest, StewartGough) {
  const testing::StewartFamily f;
  expectPasses(f, 40);
  expectFailsWithoutOneRoot(f);
}

}  // namespace
}  // namespace relpos::complete
