// Rule properties, for every registered rule: applied to pairs of fundamental constraints that a
// known pose satisfies, a rule never answers "incompatible", never drops a constraint the known
// pose needs, and the known pose satisfies one of its replacement sets. And every registered rule
// fires on some covering problem.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "random_problems.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/conformance.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {
using plugins::fundamentalResidual;

// Every rule case the registry knows (a rule without cases counts as one).
std::vector<std::string> allCaseNames() {
  std::vector<std::string> names;
  for (const auto& rule : builtinRegistry().rules()) {
    if (rule.cases.empty()) names.push_back(rule.name);
    for (const auto& c : rule.cases) names.push_back(c.name);
  }
  return names;
}

// All fundamental constraints of the problem's first alternative that the known pose satisfies.
std::vector<Fundamental> satisfiedFundamentals(const KnownProblem& kp) {
  std::vector<Fundamental> out;
  for (std::size_t i = 0; i < kp.problem.constraints.size(); ++i) {
    const InputConstraint& c = kp.problem.constraints[i];
    Decomposition d;
    const ConstraintType* type = builtinRegistry().constraintType(c.type);
    type->decompose(c, c.fixed.placed(kp.problem.fixed.pose), SourceMask{1} << i, d,
                    type->context);
    for (const auto& alt : d.alternatives) {
      bool ok = true;
      for (const Fundamental& f : alt) ok = ok && fundamentalResidual(f, kp.X_WM_star) < 1e-9;
      if (!ok) continue;
      for (const Fundamental& f : alt) out.push_back(f);
      break;
    }
  }
  return out;
}

// The conformance kit's check, against the built-in registry.
bool outputImpliesInputs(const std::vector<Fundamental>& output, const Fundamental& a,
                         const Fundamental& b, const Tolerance& tol, std::mt19937_64& rng,
                         std::string* bad) {
  return plugins::outputImpliesInputs(builtinRegistry(), output, a, b, tol, rng, bad);
}

TEST(RuleProperties, RulesKeepTheKnownSolution) {
  const Registry& reg = builtinRegistry();
  Rng rng(4242);
  const auto& kinds = singleKinds();
  std::map<std::string, int> fired;
  std::mt19937_64 sampler(17);
  int checked_converse = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const bool grid = trial % 2;
    KnownProblem kp = emptyKnownProblem(rng, grid);
    NamedFeature shared;
    for (int k = 0; k < 2; ++k) {
      addConstraint(kp, kinds[rng.integer(0, static_cast<int>(kinds.size()) - 1)], rng, grid,
                    k && trial % 3 ? &shared : nullptr);
      if (k == 0) shared = kp.problem.mobile.features.back();
    }
    const Tolerance tol = Tolerance::forScale(kp.problem.lengthScale());
    std::vector<Fundamental> fs = satisfiedFundamentals(kp);
    for (std::size_t i = 0; i < fs.size(); ++i)
      for (std::size_t j = 0; j < fs.size(); ++j) {
        if (i == j) continue;
        for (const auto& e : reg.rulesFor(fs[i].kind, fs[j].kind)) {
          const RuleInfo& rule = reg.rules()[e.rule];
          const Fundamental& a = e.swapped ? fs[j] : fs[i];
          const Fundamental& b = e.swapped ? fs[i] : fs[j];
          RuleOutput out;
          rule.fn(a, b, tol, out, rule.context);
          const std::string name = rule.firedName(out.fired);
          SCOPED_TRACE(name + " trial " + std::to_string(trial) + " known pose " +
                       poseText(kp.X_WM_star));
          if (out.verdict != RuleVerdict::kNoChange) {
            ++fired[name];
            EXPECT_TRUE(rule.cases.empty() || out.fired >= 0) << rule.name << " fired no case";
            // A value its case table has no row for (an enum longer than the table).
            EXPECT_LT(out.fired, static_cast<int>(rule.cases.size())) << rule.name;
          }
          ASSERT_NE(out.verdict, RuleVerdict::kIncompatible) << out.reason;
          std::string bad;
          if (out.verdict == RuleVerdict::kRedundantFirst ||
              out.verdict == RuleVerdict::kRedundantSecond) {
            // The kept constraint alone implies the dropped one.
            const Fundamental& kept = out.verdict == RuleVerdict::kRedundantFirst ? b : a;
            if (outputImpliesInputs({kept}, a, b, tol, sampler, &bad)) ++checked_converse;
            EXPECT_TRUE(bad.empty()) << "dropped a constraint its partner does not imply: " << bad;
            continue;
          }
          if (out.verdict != RuleVerdict::kReplace) continue;
          for (const auto& alt : out.alternatives) {
            std::vector<Fundamental> fs(alt.begin(), alt.end());
            if (outputImpliesInputs(fs, a, b, tol, sampler, &bad)) ++checked_converse;
            EXPECT_TRUE(bad.empty())
                << "a replacement set admits a pose violating the pair: " << bad;
          }
          bool some = false;
          for (const auto& alt : out.alternatives) {
            bool all = true;
            for (const Fundamental& f : alt)
              all = all && fundamentalResidual(f, kp.X_WM_star) < 1e-6;
            some = some || all;
          }
          EXPECT_TRUE(some) << "the known pose satisfies no replacement set";
        }
      }
  }
  for (const std::string& name : allCaseNames())
    if (fired[name] == 0) std::printf("[property test] never fired: %s\n", name.c_str());
  std::printf("[property test] output-implies-input checked on %d rule outputs\n",
              checked_converse);
  EXPECT_GT(checked_converse, 500);
}

// The converse half of the rule property on the bundled problems (one per rule case): for every
// pair of fundamental constraints a rule rewrites, every sampled pose of the synthesised output
// satisfies both inputs. Every case that produces an output is checked at least once.
TEST(RuleProperties, OutputsImplyInputsOnBundledProblems) {
  const Registry& reg = builtinRegistry();
  std::mt19937_64 sampler(23);
  std::map<std::string, int> checked;
  for (const char* dir : {RELPOS_DATA_DIR "/rules", RELPOS_DATA_DIR "/examples"}) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), reg);
      ASSERT_TRUE(r.problem);
      const Problem& p = *r.problem;
      const Tolerance tol = Tolerance::forScale(p.lengthScale());
      std::vector<Fundamental> fs;
      for (std::size_t i = 0; i < p.constraints.size(); ++i) {
        Decomposition d;
        const InputConstraint& c = p.constraints[i];
        const ConstraintType* type = reg.constraintType(c.type);
        type->decompose(c, c.fixed.placed(p.fixed.pose), SourceMask{1} << i, d, type->context);
        if (!d.alternatives.empty())
          for (const Fundamental& f : d.alternatives[0]) fs.push_back(f);
      }
      for (std::size_t i = 0; i < fs.size(); ++i)
        for (std::size_t j = 0; j < fs.size(); ++j) {
          if (i == j) continue;
          for (const auto& entry : reg.rulesFor(fs[i].kind, fs[j].kind)) {
            const RuleInfo& rule = reg.rules()[entry.rule];
            const bool ranged = !fs[i].exact() || !fs[j].exact();
            if (ranged && !rule.handles_ranges) continue;
            const Fundamental& a = entry.swapped ? fs[j] : fs[i];
            const Fundamental& b = entry.swapped ? fs[i] : fs[j];
            RuleOutput out;
            rule.fn(a, b, tol, out, rule.context);
            const std::string name = rule.firedName(out.fired);
            SCOPED_TRACE(name + " in " + e.path().string());
            std::string bad;
            if (out.verdict == RuleVerdict::kRedundantFirst ||
                out.verdict == RuleVerdict::kRedundantSecond) {
              const Fundamental& kept = out.verdict == RuleVerdict::kRedundantFirst ? b : a;
              if (outputImpliesInputs({kept}, a, b, tol, sampler, &bad)) ++checked[name];
            } else if (out.verdict == RuleVerdict::kReplace) {
              for (const auto& alt : out.alternatives) {
                std::vector<Fundamental> output(alt.begin(), alt.end());
                if (outputImpliesInputs(output, a, b, tol, sampler, &bad)) ++checked[name];
              }
            }
            EXPECT_TRUE(bad.empty()) << bad;
          }
        }
    }
  }
  for (const std::string& name : allCaseNames()) {
    const bool no_output = name.find("incompatible") != std::string::npos ||
                           name.find("disjoint") != std::string::npos;
    if (!no_output) {
      EXPECT_GT(checked[name], 0) << "no output of " << name << " was sampled";
    }
  }
}

// The product's promise: every registered rule case fires on some bundled problem (data/rules has
// one per case, data/examples the end-to-end tasks). A new case without a covering problem fails.
TEST(RuleCoverage, EveryRegisteredRuleCaseFiresOnABundledProblem) {
  std::set<std::string> fired;
  for (const char* dir : {RELPOS_DATA_DIR "/examples", RELPOS_DATA_DIR "/rules"}) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      ASSERT_TRUE(r.problem);
      Solution s = solve(*r.problem, builtinRegistry());
      for (const char* name : s.ruleNames()) fired.insert(name);
    }
  }
  for (const std::string& name : allCaseNames())
    EXPECT_TRUE(fired.count(name)) << "no bundled problem fires " << name;
}

TEST(Combination, InconsistentNamesTheConflictingInputs) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("B", Feature::makePoint({5, 0, 0}))
      .addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("Q", Feature::makePoint({1, 0, 0}));
  p.addConstraint("coincident", "S", "P");  // 0: unrelated
  p.addConstraint("coincident", "A", "P");  // 1
  p.addConstraint("coincident", "B", "Q");  // 2: |PQ| = 1 but |AB| = 5
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kInconsistent);
  EXPECT_EQ(s.conflicts, (std::vector<int>{1, 2}));
  EXPECT_FALSE(s.message.empty());
}

TEST(Combination, RedundantConstraintIsReported) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint({0, 0, 0}))
      .addFixedFeature("S", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("P", Feature::makePoint({0, 0, 0}));
  p.addConstraint("coincident", "A", "P");
  p.addConstraint("coincident", "S", "P");  // implied: A lies on S
  Solution s = solve(p, builtinRegistry());
  ASSERT_EQ(s.status, Status::kSolved);
  EXPECT_EQ(s.redundant, (std::vector<int>{1}));
  EXPECT_EQ(s.branches[0].manifold->dof(), 3);
}

}  // namespace
}  // namespace relpos::test
