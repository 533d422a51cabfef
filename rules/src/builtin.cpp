#include "relpos/rules/builtin.hpp"

#include "family.hpp"

namespace relpos::rules {

namespace {
struct ListedFamily {
  const char* id;  // as in families.def: the family's file spelling
  const RuleFamily* family;
};
// families.def, in its order (the registration order, which decides which rule a pair meets
// first).
constexpr ListedFamily kFamilies[] = {
#define RELPOS_RULE_FAMILY(id) {#id, &families::id},
#include "families.def"
#undef RELPOS_RULE_FAMILY
};
}  // namespace

RuleInfo ruleInfo(const RuleFamily& f) {
  RuleInfo info;
  info.name = f.name;
  info.citation = f.citation;
  info.first = f.first;
  info.second = f.second;
  info.fn = f.fn;
  info.handles_ranges = f.handles_ranges;
  info.cases.reserve(f.case_count);
  for (std::size_t i = 0; i < f.case_count; ++i)
    info.cases.push_back({info.name + "/" + f.cases[i].name, f.cases[i].citation});
  return info;
}

void registerBuiltinRules(Registry& r) {
  for (const ListedFamily& f : kFamilies) r.addRule(ruleInfo(*f.family));
}

std::vector<std::string> builtinFamilyIds() {
  std::vector<std::string> ids;
  for (const ListedFamily& f : kFamilies) ids.push_back(f.id);
  return ids;
}

std::string fileSpelling(const std::string& rule_name) {
  std::string s;
  for (char c : rule_name) {
    if (c == '+' || c == ':')
      s += '_';
    else if (c == '/')
      s += "--";
    else
      s += c;
  }
  return s;
}

}  // namespace relpos::rules
