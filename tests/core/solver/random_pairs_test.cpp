// Randomised problems of two and three constraints built around a known pose, over every pair of
// single-constraint kinds, with fresh and with shared mobile features, on generic and on
// axis-aligned integer geometry. A correct solver may answer `unhandled` (the PMF rule set is not
// complete) but never `inconsistent`, never a branch with a violating pose, and a `solved` answer
// must contain the known pose.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "evaluator.hpp"
#include "local_dof.hpp"
#include "random_problems.hpp"
#include "solve_helpers.hpp"
#include "spec_writer.hpp"
#include "test_fallback.hpp"

namespace relpos::test {
namespace {

struct Tally {
  int solved = 0, unhandled = 0, dof_checked = 0;
};

void checkKnown(const KnownProblem& kp, std::uint64_t seed, Tally& tally) {
  ASSERT_LT(worstViolation(kp.problem, kp.X_WM_star), 1e-9 + 100 * kp.noise) << "generator bug";
  Solution s = solve(kp.problem, sweepRegistry());
  ASSERT_NE(s.status, Status::kInconsistent)
      << "false inconsistent: " << s.message << "\nknown pose " << poseText(kp.X_WM_star);
  if (s.status == Status::kUnhandled) {
    ++tally.unhandled;
    // RELPOS_VERBOSE=1 lists what was left unhandled, for deciding which rule to add next.
    // and the spec, for `relpos solve` to reproduce it.
    if (std::getenv("RELPOS_VERBOSE"))
      std::printf("  unhandled: %s\n  spec: %s\n", s.message.c_str(),
                  specJson(kp.problem).c_str());
    return;
  }
  ASSERT_EQ(s.status, Status::kSolved);
  ++tally.solved;
  std::string where;
  EXPECT_LT(worstSampledViolation(kp.problem, s, 16, seed, &where), 1e-7) << where;
  // With noise the exact solutions of the perturbed problem can sit sqrt(noise) away from the
  // known pose (two solutions splitting at a tangency), so the containment test allows for that.
  // An answer not proven complete (the numeric stage's, docs/spec.md §8.3) need not hold the
  // known pose: its branches are each checked above, its list may miss some (a special geometry's
  // positive-dimensional set of poses beside the isolated ones it certified).
  if (!s.complete) return;
  const double reach = std::max(1e-6, 100 * std::sqrt(kp.noise));
  const int dof = dofOfBranchesContaining(s, kp.X_WM_star, reach);
  EXPECT_GE(dof, 0) << describeBranches(s) << "\nknown pose " << poseText(kp.X_WM_star);
  if (dof >= 0 && kp.noise == 0.0 && !kp.special) {
    // The branch through the known pose has the dimension of the solution set there, measured
    // independently by the rank of the constraints' Jacobian (generic geometry only: integer
    // geometry puts known poses on branch crossings, where the rank drops).
    EXPECT_EQ(dof, localDof(kp.problem, kp.X_WM_star))
        << describeBranches(s) << "\nknown pose " << poseText(kp.X_WM_star);
    ++tally.dof_checked;
  }
}

void runPairs(bool grid, bool share, std::uint64_t seed, double noise = 0.0) {
  Rng rng(seed);
  const auto& kinds = singleKinds();
  Tally tally;
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    for (std::size_t j = i; j < kinds.size(); ++j, ++n) {
      SCOPED_TRACE(std::string(kinds[i].label) + " + " + kinds[j].label);
      KnownProblem kp = emptyKnownProblem(rng, grid);
      kp.noise = noise;
      kp.special = grid;
      addConstraint(kp, kinds[i], rng, grid);
      const NamedFeature* reuse = share ? &kp.problem.mobile.features.back() : nullptr;
      NamedFeature copy = reuse ? *reuse : NamedFeature{};
      addConstraint(kp, kinds[j], rng, grid, reuse ? &copy : nullptr);
      checkKnown(kp, seed + n, tally);
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  std::printf("[pairs grid=%d share=%d] solved %d, unhandled %d (%.1f%% solved), DOF checked %d\n",
              grid, share, tally.solved, tally.unhandled,
              100.0 * tally.solved / (tally.solved + tally.unhandled), tally.dof_checked);
}

TEST(RandomPairs, GenericFresh) { runPairs(false, false, 11); }
TEST(RandomPairs, GenericShared) { runPairs(false, true, 12); }
TEST(RandomPairs, GridFresh) { runPairs(true, false, 13); }
TEST(RandomPairs, GridShared) { runPairs(true, true, 14); }
// Integer geometry blurred by rounding-level noise (a few ulps of its coordinates): special cases
// within the tolerance, not exactly on it. The length tolerance is relative to the problem's own
// size, and two pins of one point on nearly the same point are a problem of the size of their
// distance: only noise below the coordinates' rounding (the tolerance's floor) is within it.
TEST(RandomPairs, NoisyGridShared) { runPairs(true, true, 15, 4e-15); }
TEST(RandomPairs, NoisyGridFresh) { runPairs(true, false, 16, 4e-15); }

// Every unordered triple of kinds; the mobile feature is shared with the previous constraint when
// the kinds allow (every other triple), on generic and on integer geometry alternately.
TEST(RandomTriples, AllTriplesOfKinds) {
  Rng rng(31);
  const auto& kinds = singleKinds();
  const std::size_t n = kinds.size();
  Tally tally;
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i; j < n; ++j)
      for (std::size_t k = j; k < n; ++k, ++count) {
        const bool grid = count % 2, share = (count / 2) % 2;
        SCOPED_TRACE(std::string(kinds[i].label) + " + " + kinds[j].label + " + " + kinds[k].label);
        KnownProblem kp = emptyKnownProblem(rng, grid);
        kp.special = grid;
        NamedFeature prev;
        for (std::size_t kind : {i, j, k}) {
          addConstraint(kp, kinds[kind], rng, grid, share && kind != i ? &prev : nullptr);
          prev = kp.problem.mobile.features.back();
        }
        checkKnown(kp, 1000 + count, tally);
        if (::testing::Test::HasFatalFailure()) return;
      }
  std::printf("[triples] %llu problems: solved %d, unhandled %d (%.1f%% solved), DOF checked %d\n",
              static_cast<unsigned long long>(count), tally.solved, tally.unhandled,
              100.0 * tally.solved / count, tally.dof_checked);
  // issue 16's floor: at most 1 % of every family unanswered
  EXPECT_LE(100 * tally.unhandled, static_cast<int>(count)) << "unhandled triples";
}

// Families PMF claims: sets on one shared mobile point (translational) and rotation-only sets.
void runFamily(const std::vector<int>& family, bool grid, bool share, int trials, int size,
               std::uint64_t seed, const char* label) {
  Rng rng(seed);
  const auto& kinds = singleKinds();
  Tally tally;
  for (int t = 0; t < trials; ++t) {
    KnownProblem kp = emptyKnownProblem(rng, grid);
    kp.special = grid;
    NamedFeature shared;
    for (int k = 0; k < size; ++k) {
      const SingleKind& kind = kinds[family[rng.integer(0, static_cast<int>(family.size()) - 1)]];
      addConstraint(kp, kind, rng, grid, share && k ? &shared : nullptr);
      if (k == 0) shared = kp.problem.mobile.features.back();
    }
    SCOPED_TRACE(std::string(label) + " trial " + std::to_string(t));
    checkKnown(kp, seed + t, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  std::printf("[%s grid=%d size=%d] solved %d of %d (%.1f%%), DOF checked %d\n", label, grid, size,
              tally.solved, trials, 100.0 * tally.solved / trials, tally.dof_checked);
}

std::vector<int> kindsWhere(bool (*pred)(const SingleKind&)) {
  std::vector<int> out;
  for (std::size_t i = 0; i < singleKinds().size(); ++i)
    if (pred(singleKinds()[i])) out.push_back(static_cast<int>(i));
  return out;
}

TEST(RandomFamilies, TranslationalOnOneMobilePoint) {
  auto fam = kindsWhere([](const SingleKind& k) {
    return k.mobile == FeatureKind::kPoint && std::string(k.type) != "angle";
  });
  for (bool grid : {false, true})
    for (int size : {2, 3}) runFamily(fam, grid, true, 150, size, 100 + size + grid, "one-point");
}

TEST(RandomFamilies, RotationalOnly) {
  auto fam = kindsWhere([](const SingleKind& k) {
    const std::string t = k.type;
    return t == "angle" || t == "parallel" || t == "perpendicular";
  });
  for (bool grid : {false, true})
    for (int size : {2, 3}) runFamily(fam, grid, false, 150, size, 200 + size + grid, "rotational");
}

}  // namespace
}  // namespace relpos::test
