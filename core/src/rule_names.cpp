#include "relpos/core/rule_names.hpp"

namespace relpos {

void RuleNames::addRule(const std::string& family, const std::vector<std::string>& cases) {
  rules_.push_back({names_.size(), cases.size()});
  names_.push_back(family);
  names_.insert(names_.end(), cases.begin(), cases.end());
}

const char* RuleNames::name(RuleCaseId id) const {
  if (id.rule >= rules_.size()) return "";
  const Rule& r = rules_[id.rule];
  const bool is_case = id.fired >= 0 && static_cast<std::size_t>(id.fired) < r.cases;
  return names_[r.first + (is_case ? 1 + static_cast<std::size_t>(id.fired) : 0)].c_str();
}

}  // namespace relpos
