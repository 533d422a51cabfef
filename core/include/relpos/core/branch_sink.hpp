#pragma once
// Where a matcher puts what it finds (MatchContext::branches): branches, appended to the solve's
// answer within its budget (SolverOptions::max_branches), and derived constraint sets, queued for
// the solver to combine and match in turn. Either call answers false once the budget is spent:
// the matcher then answers MatchResult::kOverflow.
#include <cstddef>
#include <utility>
#include <vector>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

class BranchSink {
 public:
  // `pending`: the solver's queue of constraint sets (nullptr: this solve cannot defer).
  BranchSink(std::vector<Branch>& branches, int max_branches,
             std::vector<ConstraintSet>* pending = nullptr)
      : branches_(branches),
        max_branches_(static_cast<std::size_t>(max_branches)),
        pending_(pending) {}

  // Appends a branch whose manifold is an M built from `args`; false (nothing appended) when
  // the solve already holds max_branches branches.
  template <typename M, typename... Args>
  bool add(Args&&... args) {
    if (full()) return false;
    branches_.emplace_back();
    branches_.back().manifold.template emplace<M>(std::forward<Args>(args)...);
    return true;
  }
  // Appends a copy of `branch`; false as above.
  bool add(const Branch& branch) {
    if (full()) return false;
    branches_.push_back(branch);
    return true;
  }
  // Queues `derived` for the solver; false when the solve holds max_branches sets or cannot
  // defer (canDefer()).
  bool defer(const ConstraintSet& derived);
  bool canDefer() const { return pending_ != nullptr; }
  bool full() const { return branches_.size() >= max_branches_; }
  std::size_t maxBranches() const { return max_branches_; }

 private:
  std::vector<Branch>& branches_;
  std::size_t max_branches_;
  std::vector<ConstraintSet>* pending_;
};

}  // namespace relpos
