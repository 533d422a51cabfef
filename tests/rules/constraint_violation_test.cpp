// The built-in types' ConstraintType::violation (rules/src/constraint_violation.cpp) against the
// independent evaluator (tests/support/evaluator.hpp) on random constraints of every kind: about
// nothing at the pose they were built around, beyond the tolerance wherever the evaluator finds
// them clearly violated.
#include <gtest/gtest.h>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"

namespace relpos::test {
namespace {

double registeredViolation(const Problem& p, const Isometry3d& X, const Tolerance& tol) {
  const InputConstraint& c = p.constraints[0];
  const ConstraintType* t = builtinRegistry().constraintType(c.type);
  EXPECT_NE(t, nullptr);
  EXPECT_NE(t->violation, nullptr) << c.type;
  if (!t || !t->violation) return 0.0;
  return t->violation(c, c.fixed.placed(p.fixed.pose), c.mobile.placed(X), tol, t->context);
}

TEST(ConstraintViolation, AgreesWithTheEvaluatorOnEveryKind) {
  Rng rng(31);
  const Tolerance tol = Tolerance::forScale(10.0, 1e-9, 1e-9);
  int clearly_violated = 0;
  for (const SingleKind& kind : singleKinds())
    for (int k = 0; k < 20; ++k) {
      KnownProblem kp = emptyKnownProblem(rng, k % 2);
      addConstraint(kp, kind, rng, k % 2);
      SCOPED_TRACE(kind.label);
      ASSERT_LE(worstViolation(kp.problem, kp.X_WM_star), 1e-9);
      EXPECT_LE(registeredViolation(kp.problem, kp.X_WM_star, tol), 1.0);
      const Isometry3d X = rng.pose();
      if (worstViolation(kp.problem, X) < 1e-6) continue;  // a pose that (nearly) holds it too
      ++clearly_violated;
      EXPECT_GT(registeredViolation(kp.problem, X, tol), 1.0);
    }
  EXPECT_GT(clearly_violated, 100);
}

}  // namespace
}  // namespace relpos::test
