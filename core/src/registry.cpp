#include "relpos/core/registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace relpos {

bool ConstraintType::accepts_pair(FeatureKind f, FeatureKind m) const {
  return std::any_of(accepts.begin(), accepts.end(),
                     [&](const FeaturePair& p) { return p.fixed == f && p.mobile == m; });
}

// " (built-in)" or " (plugin PATH)": where an item that threw comes from.
std::string originNote(const std::string& origin) {
  return origin == "built-in" ? " (built-in)" : " (plugin " + origin + ")";
}

void ConstraintType::checkValues(const InputConstraint& c,
                                 std::vector<std::string>& problems) const {
  if (!check) return;
  std::string what;
  try {
    check(c, problems, context);
    return;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "an exception that is not a std::exception";
  }
  problems.push_back("type: constraint type '" + name + "'" + originNote(origin) +
                     " threw in its value check: " + what);
}

void Registry::checkOpen() const {
  if (frozen_) throw std::logic_error("relpos::Registry is frozen: register before solving");
}

namespace {
template <typename T>
void addNamed(std::vector<T>& items, T item, bool replace, const char* what,
              const std::string& origin) {
  if (!origin.empty()) item.origin = origin;
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
  addNamed(types_, std::move(t), replace || allow_replace_, "constraint type", origin_);
}

void Registry::addRule(RuleInfo r, bool replace) {
  checkOpen();
  if (!r.fn) throw std::invalid_argument("rule '" + r.name + "' has no function");
  addNamed(rules_, std::move(r), replace || allow_replace_, "rule", origin_);
  if (rules_.size() > 0xffff) throw std::invalid_argument("more than 65535 rules");
  // Rebuild the dispatch table and the name table: cheap, happens only at set-up, keeps
  // registration order. A new name table each time: Solutions may share the previous one.
  auto names = std::make_shared<RuleNames>();
  std::vector<std::string> cases;
  for (auto& row : table_)
    for (auto& cell : row) cell.clear();
  for (int i = 0; i < static_cast<int>(rules_.size()); ++i) {
    int a = static_cast<int>(rules_[i].first), b = static_cast<int>(rules_[i].second);
    table_[a][b].push_back({i, false});
    if (a != b) table_[b][a].push_back({i, true});
    cases.clear();
    for (int k = 0; k < static_cast<int>(rules_[i].cases.size()); ++k)
      cases.push_back(rules_[i].firedName(k));
    names->addRule(rules_[i].firedName(-1), cases);
  }
  rule_names_ = std::move(names);
}

void Registry::addManifold(ManifoldInfo m, bool replace) {
  checkOpen();
  addNamed(manifolds_, std::move(m), replace || allow_replace_, "manifold", origin_);
}

void Registry::addMatcher(MatcherInfo m, bool replace) {
  checkOpen();
  if (!m.fn) throw std::invalid_argument("matcher '" + m.name + "' has no function");
  m.library = origin_.empty() ? nullptr : origin_library_;
  addNamed(matchers_, std::move(m), replace || allow_replace_, "matcher", origin_);
}

std::uint16_t Registry::addCustomKind(CustomKindInfo k) {
  checkOpen();
  if (!k.residual) throw std::invalid_argument("custom kind '" + k.name + "' has no residual");
  if (!origin_.empty()) k.origin = origin_;
  for (std::size_t i = 0; i < custom_kinds_.size(); ++i) {
    if (custom_kinds_[i].name != k.name) continue;
    if (custom_kinds_[i].origin != k.origin && !allow_replace_)
      throw std::invalid_argument("custom kind '" + k.name + "' is already registered (by " +
                                  custom_kinds_[i].origin + ")");
    custom_kinds_[i] = std::move(k);
    return static_cast<std::uint16_t>(i);
  }
  custom_kinds_.push_back(std::move(k));
  return static_cast<std::uint16_t>(custom_kinds_.size() - 1);
}

void Registry::setFallback(FallbackInfo f, bool replace) {
  checkOpen();
  if (!f.fn) throw std::invalid_argument("fallback '" + f.name + "' has no function");
  if (fallback_.fn && !replace && !allow_replace_)
    throw std::invalid_argument("fallback '" + f.name + "': the numeric stage '" + fallback_.name +
                                "' is already registered (by " + fallback_.origin + ")");
  if (!origin_.empty()) f.origin = origin_;
  f.library = origin_.empty() ? nullptr : origin_library_;
  fallback_ = std::move(f);
}

const CustomKindInfo* Registry::customKind(const std::string& name) const {
  for (const auto& k : custom_kinds_)
    if (k.name == name) return &k;
  return nullptr;
}

void Registry::setOrigin(std::string origin, bool allow_replace) {
  origin_ = std::move(origin);
  origin_library_ = libraryPath(origin_);
  allow_replace_ = allow_replace;
}

void Registry::clearOrigin() {
  origin_.clear();
  origin_library_ = nullptr;
  allow_replace_ = false;
}

namespace {
struct LibraryNode {
  std::shared_ptr<const void> library, previous;
  std::string path;
};
}  // namespace

void Registry::keepLoaded(const std::string& path, std::shared_ptr<const void> library) {
  plugin_paths_.push_back(path);
  libraries_ =
      std::make_shared<const LibraryNode>(LibraryNode{std::move(library), libraries_, path});
}

const char* Registry::libraryPath(const std::string& origin) const {
  for (const void* n = libraries_.get(); n;) {
    const auto* node = static_cast<const LibraryNode*>(n);
    if (node->path == origin) return node->path.c_str();
    n = node->previous.get();
  }
  return nullptr;
}

const ConstraintType* Registry::constraintType(const std::string& name) const {
  for (const auto& t : types_)
    if (t.name == name) return &t;
  return nullptr;
}

}  // namespace relpos
