#include "relpos/core/branch_sink.hpp"

namespace relpos {

bool BranchSink::defer(const ConstraintSet& derived) {
  // The capacity check keeps the set a matcher is reading from (an element of *pending_) valid:
  // no reallocation.
  if (!pending_ || pending_->size() >= max_branches_ || pending_->size() == pending_->capacity())
    return false;
  pending_->push_back(derived);
  pending_->back().tested.clear();
  return true;
}

}  // namespace relpos
