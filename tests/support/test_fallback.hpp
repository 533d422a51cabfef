#pragma once
// A stand-in for the numeric stage (docs/spec.md §8) in the core and io tests: a fallback that
// answers with one certified pose it was told, so the solver's hook, its guard and the writer's
// fields can be tested without relpos_complete. And a problem the rules leave `unhandled`.
#include <string>

#include "relpos/core/registry.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::test {

// What the test fallback does when called (its context).
struct TestFallback {
  enum class Answer { kPose, kInconsistent, kDecline, kThrow, kNaNCertificate };
  Answer answer = Answer::kPose;
  Isometry3d pose = Isometry3d::Identity();  // kPose: the branch's one pose
  Certificate certificate{1e-12, 2e-12};     // kPose: its certificate
  bool complete = true;                      // kPose: the proof it claims
  mutable int calls = 0;                     // how often the solver called it
};

// The built-ins' rules alone (every constraint type, rule, manifold and matcher, no numeric
// stage, whether or not registerBuiltins adds one), frozen: what "the rules' answer" means.
const Registry& rulesOnlyRegistry();
// The built-ins with the numeric stage limited to the stored start systems (StageOptions), frozen:
// for the sweeps over thousands of random problems that test the rules and the solver, where each
// new constraint signature would otherwise compute a start system for seconds; its charts from 6
// starts, at most 3 (the defaults: 12 and 8). The stage itself is swept with builtinRegistry() in
// tests/complete.
const Registry& sweepRegistry();
// Those with `stage` registered as the numeric stage (named "test-stage").
Registry builtinsWithFallback(const TestFallback& stage);

// Six point-point distances between three fixed and three mobile points (a 3-3 platform), measured
// at X_WM: X_WM satisfies them, and no rule reduces them (the answer without a numeric stage is
// `unhandled`).
Problem platformProblem(const Isometry3d& X_WM);
// The pose platformProblem is measured at in the tests: a turn of 0.4 rad about (1, 2, 3) and a
// shift by (0.5, 0.7, 2).
Isometry3d platformPose();

}  // namespace relpos::test
