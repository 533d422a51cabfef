#pragma once
// Which rule case fired, as an id (RuleCaseId), and the immutable table that names the ids
// (RuleNames). A Solution records ids and shares the table, so the names it reports stay valid
// after the Registry that solved it is gone.
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

namespace relpos {

struct RuleCaseId {
  std::uint16_t rule = 0;   // index into Registry::rules()
  std::int16_t fired = -1;  // index into RuleInfo::cases (RuleOutput::fired); -1: the rule itself
  bool operator==(const RuleCaseId& o) const { return rule == o.rule && fired == o.fired; }
};

class RuleNames {
 public:
  // Appends a rule: its family name, then its cases' names in case order.
  void addRule(const std::string& family, const std::vector<std::string>& cases);
  // The name of the case `id` names, or the rule's own name when id.fired names no case (as
  // RuleInfo::firedName); "" for an id of no rule.
  const char* name(RuleCaseId id) const;

 private:
  struct Rule {
    std::size_t first;  // names_[first]: the family; names_[first + 1 + k]: case k
    std::size_t cases;
  };
  std::vector<Rule> rules_;
  std::vector<std::string> names_;
};

// The names of a list of ids, in order, as a range: `for (const char* name : view)`.
class RuleCaseNames {
 public:
  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = const char*;
    using difference_type = std::ptrdiff_t;
    using pointer = const char* const*;
    using reference = const char*;
    iterator(const RuleNames* table, const RuleCaseId* at) : table_(table), at_(at) {}
    const char* operator*() const { return table_->name(*at_); }
    iterator& operator++() {
      ++at_;
      return *this;
    }
    iterator operator++(int) {
      iterator was = *this;
      ++at_;
      return was;
    }
    bool operator==(const iterator& o) const { return at_ == o.at_; }
    bool operator!=(const iterator& o) const { return at_ != o.at_; }

   private:
    const RuleNames* table_;
    const RuleCaseId* at_;
  };
  RuleCaseNames(const RuleNames* table, const std::vector<RuleCaseId>& ids)
      : table_(table), ids_(ids) {}
  iterator begin() const { return {table_, ids_.data()}; }
  iterator end() const { return {table_, ids_.data() + ids_.size()}; }
  std::size_t size() const { return ids_.size(); }

 private:
  const RuleNames* table_;
  const std::vector<RuleCaseId>& ids_;
};

}  // namespace relpos
