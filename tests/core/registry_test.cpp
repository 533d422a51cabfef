#include <gtest/gtest.h>

#include <set>

#include "relpos/builtins/builtins.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

void noRule(const Fundamental&, const Fundamental&, const Tolerance&, RuleOutput&, const void*) {}

TEST(Registry, DuplicateNamesAreRejectedUnlessReplacing) {
  Registry r;
  registerBuiltins(r);
  EXPECT_THROW(registerBuiltins(r), std::invalid_argument);
  RuleInfo rule;
  rule.name = "pp+pp";
  rule.citation = "test";
  rule.first = rule.second = FundamentalKind::kPointPoint;
  rule.fn = &noRule;
  EXPECT_THROW(r.addRule(rule), std::invalid_argument);
  EXPECT_NO_THROW(r.addRule(rule, /*replace=*/true));
  EXPECT_EQ(r.rules().size(), builtinRegistry().rules().size());
}

TEST(Registry, FrozenRegistryRefusesAdditions) {
  Registry r;
  r.freeze();
  EXPECT_THROW(r.addMatcher({"m", nullptr}), std::logic_error);
}

TEST(Registry, DispatchTableHasBothOrders) {
  const Registry& r = builtinRegistry();
  const auto& pp_pl = r.rulesFor(FundamentalKind::kPointPoint, FundamentalKind::kPointLine);
  const auto& pl_pp = r.rulesFor(FundamentalKind::kPointLine, FundamentalKind::kPointPoint);
  ASSERT_EQ(pp_pl.size(), pl_pp.size());
  ASSERT_FALSE(pp_pl.empty());
  EXPECT_FALSE(pp_pl[0].swapped);
  EXPECT_TRUE(pl_pp[0].swapped);
  EXPECT_EQ(pp_pl[0].rule, pl_pp[0].rule);
}

TEST(Registry, EveryRuleCaseHasAUniqueNameAndACitation) {
  std::set<std::string> names;
  for (const auto& rule : builtinRegistry().rules()) {
    EXPECT_FALSE(rule.name.empty());
    auto cites = [](const std::string& c) {
      return c.find("PMF") != std::string::npos || c.find("Somani") != std::string::npos;
    };
    EXPECT_TRUE(cites(rule.citation)) << rule.name;
    for (const auto& c : rule.cases) {
      EXPECT_EQ(c.name.rfind(rule.name + "/", 0), 0u)
          << c.name << " is not in family " << rule.name;
      EXPECT_TRUE(cites(c.citation)) << c.name;
      EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    }
  }
}

bool noAnswer(const Problem&, const Registry&, const Tolerance&, Solution&, const void*) {
  return false;
}

// The numeric stage's hook: one per registry, frozen like the rest, stamped with its origin.
TEST(Registry, OneFallbackStampedWithItsOrigin) {
  Registry r;
  EXPECT_EQ(r.fallback(), nullptr);
  EXPECT_THROW(r.setFallback({"none", nullptr}), std::invalid_argument);
  EXPECT_EQ(r.fallback(), nullptr);
  static const int state = 7;
  r.setFallback({"first", &noAnswer, &state});
  ASSERT_NE(r.fallback(), nullptr);
  EXPECT_EQ(r.fallback()->name, "first");
  EXPECT_EQ(r.fallback()->context, &state);
  EXPECT_EQ(r.fallback()->origin, "built-in");
  EXPECT_EQ(r.fallback()->library, nullptr);
  try {
    r.setFallback({"second", &noAnswer});
    ADD_FAILURE() << "a second fallback was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "fallback 'second': the numeric stage 'first' is already registered (by "
                 "built-in)");
  }
  r.setOrigin("/plugins/numeric.so", /*allow_replace=*/true);
  r.setFallback({"second", &noAnswer});
  r.clearOrigin();
  EXPECT_EQ(r.fallback()->name, "second");
  EXPECT_EQ(r.fallback()->origin, "/plugins/numeric.so");
  EXPECT_EQ(r.fallback()->library, nullptr);  // no library was kept for that path
  r.freeze();
  EXPECT_THROW(r.setFallback({"third", &noAnswer}, /*replace=*/true), std::logic_error);
  EXPECT_EQ(r.fallback()->name, "second");
}

}  // namespace
}  // namespace relpos::test
