// The built-in rule families as registered (rules/src/builtin.cpp, families.def): one spelling
// per family, cases named after their family, the registration order that decides which rule a
// pair meets first.
#include "relpos/rules/builtin.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "relpos/core/rule.hpp"

namespace relpos::test {
namespace {

Registry rulesOnly() {
  Registry r;
  rules::registerBuiltinRules(r);
  return r;
}

TEST(BuiltinRules, FileSpellingMapsPlusColonAndSlash) {
  EXPECT_EQ(rules::fileSpelling("pp+pplane"), "pp_pplane");
  EXPECT_EQ(rules::fileSpelling("pp+pplane/circle"), "pp_pplane--circle");
  EXPECT_EQ(rules::fileSpelling("range:pline+pplane/two-strips"), "range_pline_pplane--two-strips");
}

TEST(BuiltinRules, EachFamilyIsListedUnderItsOwnSpelling) {
  const Registry r = rulesOnly();
  const std::vector<std::string> ids = rules::builtinFamilyIds();
  ASSERT_EQ(ids.size(), r.rules().size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    EXPECT_EQ(rules::fileSpelling(r.rules()[i].name), ids[i]);
}

TEST(BuiltinRules, CasesAreNamedFamilySlashCaseWithACitation) {
  const Registry r = rulesOnly();
  for (const RuleInfo& rule : r.rules()) {
    EXPECT_FALSE(rule.cases.empty()) << rule.name;
    EXPECT_FALSE(rule.citation.empty()) << rule.name;
    for (const RuleCase& c : rule.cases) {
      EXPECT_EQ(c.name.rfind(rule.name + "/", 0), 0u) << c.name;
      EXPECT_GT(c.name.size(), rule.name.size() + 1) << c.name;
      EXPECT_FALSE(c.citation.empty()) << c.name;
    }
  }
}

// The order the solver asks the rules in (the first that changes a pair decides it): the
// pinned-point families before the PMF tables, the range families last.
TEST(BuiltinRules, RegistrationOrderIsFamiliesDefOrder) {
  const std::vector<std::string> want = {"pp0+pp",
                                         "pp0+pl",
                                         "pp0+pplane",
                                         "pp+pp",
                                         "pp+pl",
                                         "pl+pl",
                                         "pp+pplane",
                                         "pl+pplane",
                                         "pplane+pplane",
                                         "pl+lp",
                                         "pl+planep",
                                         "angle+angle",
                                         "range:pplane+pplane",
                                         "range:pp+pp",
                                         "range:pl+pl",
                                         "range:pline+pplane"};
  const Registry r = rulesOnly();
  std::vector<std::string> got;
  for (const RuleInfo& rule : r.rules()) got.push_back(rule.name);
  EXPECT_EQ(got, want);
}

TEST(BuiltinRules, OnlyTheRangeFamiliesSeeRanges) {
  const Registry r = rulesOnly();
  for (const RuleInfo& rule : r.rules())
    EXPECT_EQ(rule.handles_ranges, rule.name.rfind("range:", 0) == 0) << rule.name;
}

TEST(RuleCaseRows, CasesInOrderChecksEachRowsValue) {
  constexpr RuleCaseRow in_order[] = {{0, "a", "x"}, {1, "b", "y"}};
  constexpr RuleCaseRow swapped[] = {{1, "b", "y"}, {0, "a", "x"}};
  static_assert(casesInOrder(in_order));
  static_assert(!casesInOrder(swapped));
}

}  // namespace
}  // namespace relpos::test
