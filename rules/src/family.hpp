#pragma once
// A built-in rule family declared in one place: its name, citation, kinds, rule and case table.
// Each family is one file rules/src/ID.cpp defining `const RuleFamily ID` in
// relpos::rules::families, ID being the family's name spelled for files (spelling.hpp); the
// one line RELPOS_RULE_FAMILY(ID) in families.def registers it (and adds the file to the build).
#include <cstddef>
#include <stdexcept>

#include "relpos/core/registry.hpp"
#include "relpos/core/rule.hpp"

namespace relpos::rules {

struct RuleFamily {
  const char* name;      // e.g. "pp+pplane"; each case is registered as "NAME/CASE"
  const char* citation;  // e.g. "PMF App. IV Table V"
  FundamentalKind first, second;
  RuleFn fn;
  const RuleCaseRow* cases;
  std::size_t case_count;
  // Whether the rule understands ranges (RuleInfo::handles_ranges).
  bool handles_ranges;
};

// A family whose case table is `cases`. Refuses a table out of order (casesInOrder): for a
// family defined constexpr, at compile time.
template <std::size_t N>
constexpr RuleFamily family(const char* name, const char* citation, FundamentalKind first,
                            FundamentalKind second, RuleFn fn, const RuleCaseRow (&cases)[N],
                            bool handles_ranges = false) {
  if (!casesInOrder(cases))
    throw std::logic_error("a rule family's case table is not in the order of its values");
  return RuleFamily{name, citation, first, second, fn, cases, N, handles_ranges};
}

// The registry's entry for `f`: its cases named "NAME/CASE".
RuleInfo ruleInfo(const RuleFamily& f);

// Every built-in family, declared from families.def (each defined in its own file).
namespace families {
#define RELPOS_RULE_FAMILY(id) extern const RuleFamily id;
#include "families.def"
#undef RELPOS_RULE_FAMILY
}  // namespace families

}  // namespace relpos::rules
