#pragma once
// The answer of a solve (docs/spec.md §2). Defaults describe a solve that never ran. A Solution can
// be reused across solves: clear() keeps every buffer's capacity, so repeated solves into the
// same Solution allocate nothing.
#include <memory>
#include <string>
#include <vector>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/core/rule_names.hpp"

namespace relpos {

enum class Status : unsigned char { kNotSolved, kSolved, kInconsistent, kUnhandled };
const char* toString(Status s);

// What proves a branch the numeric stage found (docs/spec.md §2.4, §8): a Krawczyk-proven box
// about the reported pose holding exactly one solution of the encoded system, so the reported
// pose is within `radius` (the box's half-width over the position, in the problem's length
// units) and `angle` (its bound on the rotation, radians) of a true solution. Both 0 for an exact
// branch, both finite and non-negative always.
struct Certificate {
  double radius = 0.0;
  double angle = 0.0;
};

struct Branch {
  ManifoldHolder manifold;
  SourceMask sources = 0;  // input constraints that shaped this branch
  // The plugin whose matcher made this branch (its path, which lives as long as
  // Solution::libraries), so that an exception its manifold throws later names it; nullptr for
  // a built-in matcher's branch.
  const char* origin = nullptr;
  // true: a closed form (a rule's or a matcher's manifold), every pose of it a solution to the
  // rounding of its arithmetic. false: found numerically and proven by `certified`.
  bool exact = true;
  Certificate certified;  // zero unless !exact
};

struct Solution {
  Solution();
  // The plugin libraries of the registry that solved it: branches may run their code. Declared
  // first so it is destroyed last, after the branches.
  std::shared_ptr<const void> libraries;
  // The names of the registry's rule cases (Registry::ruleNames), which `rules` indexes.
  std::shared_ptr<const RuleNames> rule_names;
  Status status = Status::kNotSolved;
  // Proven that no solution is missing: the branches (none, when inconsistent) are every pose
  // that satisfies the constraints. The solver sets it for an answer of the rules (their closed
  // forms enumerate every branch): true when solved or inconsistent, false when unhandled; the
  // numeric stage (Registry::fallback) sets it from its proof (docs/spec.md §2.2, §8). An
  // inconsistent answer is always complete; an unhandled one never is.
  bool complete = false;
  // Proven that no isolated solution is missing (docs/spec.md §2.2, §8.3): every pose that is
  // alone in its neighbourhood among the solutions is on a branch. Implied by `complete`; the
  // numeric stage proves it (every isolated root of the encoded system found and certified)
  // where it cannot prove `complete` (a positive-dimensional set of poses is not excluded).
  bool isolated_complete = false;
  std::string message = "relpos::solve was not called.";
  std::vector<Branch> branches;
  std::vector<int> conflicts;     // input constraint indices (inconsistent)
  std::vector<int> redundant;     // input constraint indices implied by the others
  std::vector<RuleCaseId> rules;  // the rule cases that fired, in order of first firing
  double solve_us = 0.0;

  void clear();
  // Records that `id` fired, unless a case of that name already did.
  void noteRule(RuleCaseId id);
  // The name of rules[i] (e.g. "pp+pp/circle"), valid as long as this Solution's rule_names.
  const char* ruleName(std::size_t i) const { return rule_names->name(rules[i]); }
  // Every rules[i]'s name, in order: `for (const char* name : solution.ruleNames())`.
  RuleCaseNames ruleNames() const { return {rule_names.get(), rules}; }
  std::string briefReport() const;
};

// `solution` answered `unhandled` instead, because code its branches run threw `what` while
// `during` (e.g. "writing the result"): the message names the plugins the branches come from.
// No branch is kept, so none of their code runs again; the rules that fired and the solve time
// are.
Solution unhandledAfterThrow(const Solution& solution, const char* during, const std::string& what);

}  // namespace relpos
