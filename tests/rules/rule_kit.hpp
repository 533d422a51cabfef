#pragma once
// For the direct tests of one rule family (tests/rules/FAMILY_test.cpp): a pair of input
// constraints as a user writes them, decomposed into the fundamentals the rule sees, the rule's
// answer, and checks against poses the independent evaluator (tests/support/evaluator.hpp) says
// satisfy the inputs.
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/rule.hpp"

namespace relpos::test {

// The fundamentals of every constraint of p (each constraint's first alternative), in order.
std::vector<Fundamental> fundamentalsOf(const Problem& p);

// Runs the built-in rule family `family` (e.g. "pp+pplane") on the first two fundamentals of p,
// in the order of the kinds it was registered for; `*case_name` is the case that fired ("" when
// none did).
RuleOutput applyRule(const std::string& family, const Problem& p, std::string* case_name,
                     const Tolerance& tol = Tolerance{});
// The same on given fundamentals (the first two): derived ones, with their uncertainty (err).
RuleOutput applyRule(const std::string& family, const std::vector<Fundamental>& fs,
                     std::string* case_name, const Tolerance& tol = Tolerance{});

// Whether X_WM satisfies every input constraint of p by the evaluator (within 1e-9).
bool satisfiesInputs(const Problem& p, const Isometry3d& X_WM);
// Whether X_WM satisfies every fundamental of one of the rule's alternatives (within 1e-9).
bool satisfiesAnAlternative(const RuleOutput& out, const Isometry3d& X_WM);

// Makes constraint i of p a range [lo, hi] instead of a value (as "min" and "max" in a spec).
void makeRange(Problem& p, std::size_t i, double lo, double hi);

// X_WM = a rotation of `angle` about `axis` then a translation by t.
Isometry3d poseOf(const Vector3d& t, double angle = 0.0, const Vector3d& axis = Vector3d::UnitZ());

}  // namespace relpos::test
