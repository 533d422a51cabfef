#pragma once
// The answer of a solve (SPEC.md §2). Defaults describe a solve that never ran. A Solution can
// be reused across solves: clear() keeps every buffer's capacity, so repeated solves into the
// same Solution allocate nothing.
#include <memory>
#include <string>
#include <vector>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos {

enum class Status : unsigned char { kNotSolved, kSolved, kInconsistent, kUnhandled };
const char* toString(Status s);

struct Branch {
  ManifoldHolder manifold;
  SourceMask sources = 0;  // input constraints that shaped this branch
  // The plugin whose matcher made this branch (its path, which lives as long as
  // Solution::libraries), so that an exception its manifold throws later names it; nullptr for
  // a built-in matcher's branch.
  const char* origin = nullptr;
};

struct Solution {
  Solution();
  // The plugin libraries of the registry that solved it: branches may run their code. Declared
  // first so it is destroyed last, after the branches.
  std::shared_ptr<const void> libraries;
  Status status = Status::kNotSolved;
  std::string message = "relpos::solve was not called.";
  std::vector<Branch> branches;
  std::vector<int> conflicts;      // input constraint indices (inconsistent)
  std::vector<int> redundant;      // input constraint indices implied by the others
  std::vector<const char*> rules;  // names of rules that fired, in order of first firing
  double solve_us = 0.0;

  void clear();
  void noteRule(const char* name);
  std::string briefReport() const;
};

// `solution` answered `unhandled` instead, because code its branches run threw `what` while
// `during` (e.g. "writing the result"): the message names the plugins the branches come from.
// No branch is kept, so none of their code runs again; the rules that fired and the solve time
// are.
Solution unhandledAfterThrow(const Solution& solution, const char* during, const std::string& what);

}  // namespace relpos
