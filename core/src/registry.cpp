#include "relpos/core/registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace relpos {

bool ConstraintType::accepts_pair(FeatureKind f, FeatureKind m) const {
  return std::any_of(accepts.begin(), accepts.end(),
                     [&](const FeaturePair& p) { return p.fixed == f && p.mobile == m; });
}

void Registry::checkOpen() const {
  if (frozen_) throw std::logic_error("relpos::Registry is frozen: register before solving");
}

namespace {
template <typename T>
void addNamed(std::vector<T>& items, T item, bool replace, const char* what) {
  auto it =
      std::find_if(items.begin(), items.end(), [&](const T& x) { return x.name == item.name; });
  if (it == items.end()) {
    items.push_back(std::move(item));
    return;
  }
  if (!replace)
    throw std::invalid_argument(std::string(what) + " '" + item.name +
                                "' is already registered (by " + it->origin + ")");
  *it = std::move(item);
}
}  // namespace

void Registry::addConstraintType(ConstraintType t, bool replace) {
  checkOpen();
  addNamed(types_, std::move(t), replace, "constraint type");
}

void Registry::addRule(RuleInfo r, bool replace) {
  checkOpen();
  if (!r.fn) throw std::invalid_argument("rule '" + r.name + "' has no function");
  addNamed(rules_, std::move(r), replace, "rule");
  // Rebuild the dispatch table: cheap, happens only at set-up, keeps registration order.
  for (auto& row : table_)
    for (auto& cell : row) cell.clear();
  for (int i = 0; i < static_cast<int>(rules_.size()); ++i) {
    int a = static_cast<int>(rules_[i].first), b = static_cast<int>(rules_[i].second);
    table_[a][b].push_back({i, false});
    if (a != b) table_[b][a].push_back({i, true});
  }
}

void Registry::addManifold(ManifoldInfo m, bool replace) {
  checkOpen();
  addNamed(manifolds_, std::move(m), replace, "manifold");
}

void Registry::addMatcher(MatcherInfo m, bool replace) {
  checkOpen();
  if (!m.fn) throw std::invalid_argument("matcher '" + m.name + "' has no function");
  addNamed(matchers_, std::move(m), replace, "matcher");
}

const ConstraintType* Registry::constraintType(const std::string& name) const {
  for (const auto& t : types_)
    if (t.name == name) return &t;
  return nullptr;
}

}  // namespace relpos
