// Repeated solves into a reused Workspace and Solution allocate nothing (docs/architecture.md "Hot
// path"). Counts every global operator new while solving.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
// The nothrow forms too (simdjson allocates its document with new (std::nothrow) T[]): left to
// the runtime, they would allocate where the replaced delete below cannot free (ASan: an
// alloc-dealloc mismatch).
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

namespace relpos::test {
namespace {

long allocationsDuring(const Problem& p, Workspace& ws, Solution& s) {
  const long before = g_allocations.load();
  solve(p, builtinRegistry(), SolverOptions(), ws, s);
  return g_allocations.load() - before;
}

TEST(Allocation, CounterSeesAllocations) {
  const long before = g_allocations.load();
  auto* v = new std::vector<int>(100);
  delete v;
  EXPECT_GE(g_allocations.load() - before, 2);
}

TEST(Allocation, RepeatedSolvesOfUpToEightConstraintsAllocateNothing) {
  Rng rng(99);
  Workspace ws;
  Solution s;
  const auto& kinds = singleKinds();
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    KnownProblem kp = emptyKnownProblem(rng, trial % 2);
    const int n = 1 + trial % 8;
    NamedFeature shared;
    for (int k = 0; k < n; ++k) {
      addConstraint(kp, kinds[rng.integer(0, static_cast<int>(kinds.size()) - 1)], rng, trial % 2,
                    k && trial % 3 ? &shared : nullptr);
      if (k == 0) shared = kp.problem.mobile.features.back();
    }
    allocationsDuring(kp.problem, ws, s);          // warm-up: buffers reach their working size
    if (s.status == Status::kUnhandled) continue;  // messages for unhandled may allocate
    // The numeric stage's answers (not complete) allocate: its encodings build polynomials.
    if (!s.complete) continue;
    SCOPED_TRACE("trial " + std::to_string(trial) + ": " + s.briefReport());
    EXPECT_EQ(allocationsDuring(kp.problem, ws, s), 0);
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Every bundled task (the worked example, ranges, mixed and revolved branches, the scenarios):
// after one warm-up solve into the same Workspace and Solution, solving again allocates nothing.
TEST(Allocation, BundledProblemsAllocateNothingAfterWarmUp) {
  int checked = 0;
  for (const char* dir : {RELPOS_DATA_DIR "/examples", RELPOS_DATA_DIR "/scenarios"}) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      ASSERT_TRUE(r.problem) << e.path();
      Workspace ws;
      Solution s;
      allocationsDuring(*r.problem, ws, s);
      if (s.status == Status::kUnhandled) continue;
      SCOPED_TRACE(e.path().string());
      for (int i = 0; i < 3; ++i) EXPECT_EQ(allocationsDuring(*r.problem, ws, s), 0);
      ++checked;
    }
  }
  EXPECT_GT(checked, 60);
}

}  // namespace
}  // namespace relpos::test
