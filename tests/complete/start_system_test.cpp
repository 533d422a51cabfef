// Start systems by monodromy, checked against the families' known generic root counts (Bézout
// for two conics; 40 for the general Stewart–Gough platform: Raghavan 1993, Wampler 1996).
#include "start_system.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "polynomial_eval.hpp"
#include "relpos/complete/fiber.hpp"
#include "test_families.hpp"

namespace relpos::complete {
namespace {

// Every root is a root (small residual) and no two are numerically equal.
void expectDistinctRoots(const Family& f, const StartSystem& s) {
  const detail::CompiledShape shape(f.shape());
  std::vector<Complex> c(shape.terms());
  f.coefficients(s.params.data(), c.data());
  detail::EvalScratch scratch(shape);
  for (std::size_t i = 0; i < s.roots.size(); ++i) {
    detail::CVec fx(shape.variables());
    detail::evaluate(shape, c.data(), nullptr, detail::CVec(s.roots[i]), scratch, &fx, nullptr,
                     nullptr);
    EXPECT_LT(fx.norm(), 1e-9 * (1.0 + s.roots[i].squaredNorm())) << "root " << i;
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GT((s.roots[i] - s.roots[j]).norm(), 1e-6) << i << " " << j;
  }
}

TEST(StartSystem, TwoConicsHaveFourRoots) {
  const testing::ConicFamily f;
  const StartSystem& s = startSystem(f);
  EXPECT_EQ(s.roots.size(), 4u);
  EXPECT_EQ(s.check, "monodromy+total-degree");
  EXPECT_EQ(s.total_degree_paths, 4);
  EXPECT_EQ(s.total_degree_added, 0);
  expectDistinctRoots(f, s);
  EXPECT_EQ(&startSystem(f), &s);  // cached
}

// Threads asking at once for a signature not yet computed get the one start system, computed
// once (the others wait for it, not for the cache's lock).
TEST(StartSystem, ThreadsAskingAtOnceShareOneComputation) {
  const testing::DenseFamily f(2, 2);
  std::vector<const StartSystem*> got(4, nullptr);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < got.size(); ++i)
    threads.emplace_back([&, i] { got[i] = &startSystem(f); });
  for (std::thread& t : threads) t.join();
  for (const StartSystem* s : got) EXPECT_EQ(s, got[0]);
  EXPECT_EQ(got[0]->roots.size(), 4u);  // Bézout
}

// A computation over its step budget stops with no roots (a solve then leaves the family to
// the charts); the same family with budget enough has all its roots.
TEST(StartSystem, AComputationOverItsStepBudgetStopsWithNoRoots) {
  const testing::DenseFamily f(2, 3);
  const auto over = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0, 10);
  EXPECT_EQ(over->check, "over the step budget");
  EXPECT_TRUE(over->roots.empty());
  const auto within = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0, 1000000);
  EXPECT_EQ(within->roots.size(), 9u);  // Bézout
}

// The budget holds the paths' steps and the root tests together: a computation fits a budget of
// exactly their sum and runs over one less (each test costs about a step where the roots crowd).
TEST(StartSystem, TheRootTestsCountInTheStepBudget) {
  const testing::DenseFamily f(2, 3);
  for (const bool cross_check : {false, true}) {
    const auto free = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0, 0, cross_check);
    ASSERT_EQ(free->roots.size(), 9u);  // Bézout
    EXPECT_GT(free->steps, 0);
    EXPECT_GE(free->root_tests, 9);  // one certificate per root added, at least
    const std::int64_t work = free->steps + free->root_tests;
    const auto fits = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0,
                                                 static_cast<std::uint64_t>(work), cross_check);
    EXPECT_EQ(fits->roots.size(), 9u) << cross_check;
    EXPECT_EQ(fits->steps, free->steps);
    EXPECT_EQ(fits->root_tests, free->root_tests);
    const auto short_one = detail::computeStartSystem(
        f, detail::kDefaultMaxBezout, 0, static_cast<std::uint64_t>(work - 1), cross_check);
    EXPECT_EQ(short_one->check, "over the step budget") << cross_check;
    EXPECT_TRUE(short_one->roots.empty());
  }
}

// While solving (findStartSystem, a step budget) the start system is monodromy's alone — a
// fixed graph of members, then loops — with every root (the cross-check is what startSystem,
// unbudgeted, and the stored ones add).
TEST(StartSystem, WhileSolvingMonodromyAloneFindsEveryRoot) {
  const testing::DenseFamily f(2, 3);
  const auto alone = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0, 1000000, false);
  EXPECT_EQ(alone->check, "monodromy");
  EXPECT_EQ(alone->total_degree_paths, 0);
  EXPECT_EQ(alone->roots.size(), 9u);  // Bézout
  expectDistinctRoots(f, *alone);
  const testing::DenseFamily g(3, 3);  // a signature no other test of this program computes
  const StartSystem* solving = findStartSystem(g, true);
  ASSERT_NE(solving, nullptr);
  EXPECT_EQ(solving->check, "monodromy");
  EXPECT_EQ(solving->roots.size(), 27u);  // Bézout
}

// The 6-6 platform's 40 roots (Dietmaier), computed the way a solve computes a start system.
TEST(StartSystem, WhileSolvingTheStewartPlatformGetsAllFortyRoots) {
  const testing::StewartFamily f;
  const auto s = detail::computeStartSystem(f, detail::kDefaultMaxBezout, 0,
                                            detail::kSolvingStepBudget, false);
  EXPECT_EQ(s->check, "monodromy");
  EXPECT_EQ(s->roots.size(), 40u);
  expectDistinctRoots(f, *s);
}

TEST(StartSystem, StewartGoughHasFortyRoots) {
  const testing::StewartFamily f;
  const auto t0 = std::chrono::steady_clock::now();
  const StartSystem& s = startSystem(f);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ::testing::Test::RecordProperty("start_system_ms", std::to_string(ms));
  std::printf("startSystem(Stewart 6-6): %.1f ms, %d loops, %s, total-degree added %d\n", ms,
              s.monodromy_loops, s.check.c_str(), s.total_degree_added);
  EXPECT_EQ(s.roots.size(), 40u);
  EXPECT_EQ(s.check, "monodromy+total-degree");
  EXPECT_EQ(s.total_degree_paths, 128);
  expectDistinctRoots(f, s);
}

class DenseStartSystem : public ::testing::TestWithParam<std::pair<int, int>> {};

// A generic dense system of n equations of degree d has d^n roots (Bézout). Computed here, with
// its cross-check: startSystem's cache may already hold a solve's (monodromy alone) for these
// signatures when the whole program runs in one process (fiber_test.cpp solves them).
TEST_P(DenseStartSystem, FindsTheBezoutNumberOfRoots) {
  const auto [n, d] = GetParam();
  const testing::DenseFamily f(n, d);
  const auto computed = detail::computeStartSystem(f, detail::kDefaultMaxBezout);
  const StartSystem& s = *computed;
  int expected = 1;
  for (int i = 0; i < n; ++i) expected *= d;
  EXPECT_EQ(static_cast<int>(s.roots.size()), expected);
  EXPECT_EQ(s.total_degree_paths, expected);
  EXPECT_EQ(s.total_degree_added, 0);  // monodromy had found them all
  expectDistinctRoots(f, s);
}

INSTANTIATE_TEST_SUITE_P(Sizes, DenseStartSystem,
                         ::testing::Values(std::make_pair(1, 4), std::make_pair(2, 3),
                                           std::make_pair(3, 2), std::make_pair(2, 4),
                                           std::make_pair(4, 2)));

// Above the Bézout limit the count is cross-checked by a second, independent monodromy run.
TEST(StartSystem, ASecondMonodromyRunAgreesWhenBezoutIsTooLarge) {
  const testing::DenseFamily f(3, 2);
  const auto s = detail::computeStartSystem(f, 4);  // Bézout 8 > 4
  EXPECT_EQ(s->check, "monodromy+second-monodromy");
  EXPECT_EQ(s->total_degree_paths, 0);
  EXPECT_EQ(s->roots.size(), 8u);
  EXPECT_EQ(s->second_monodromy_roots, 8);
  EXPECT_EQ(s->second_monodromy_added, 0);
  expectDistinctRoots(f, *s);
}

}  // namespace
}  // namespace relpos::complete
