#pragma once
// A combination rule (PMF §IV): looks at two fundamental constraints and answers no-change,
// incompatible (with a reason), redundant (drop one), or replace the pair by one or more
// alternative sets (more than one = the problem branches). "Add an implicit rotation" is a
// replacement whose set holds the rotation beside the constraint(s) it keeps.
#include <array>

#include "relpos/core/fixed_vector.hpp"
#include "relpos/core/fundamental.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos {

enum class RuleVerdict : unsigned char {
  kNoChange,
  kIncompatible,
  kRedundantFirst,   // the first constraint is implied by the second: drop it
  kRedundantSecond,  // the second is implied by the first: drop it
  kReplace,
};

inline constexpr std::size_t kMaxRuleAlternatives = 4;
inline constexpr std::size_t kMaxRuleOutputs = 4;

struct RuleOutput {
  RuleVerdict verdict = RuleVerdict::kNoChange;
  const char* reason = "";  // static text, for kIncompatible
  int fired = -1;           // which case of the rule applied (index into RuleInfo::cases)
  bool deferred = false;    // no change for now: Tolerance::tooIllConditioned (asked again later)
  FixedVector<FixedVector<Fundamental, kMaxRuleOutputs>, kMaxRuleAlternatives> alternatives;

  void reset() {
    verdict = RuleVerdict::kNoChange;
    reason = "";
    fired = -1;
    deferred = false;
    alternatives.clear();
  }
  // Records which case of the rule applies; returns *this for chaining.
  RuleOutput& fire(int rule_case) {
    fired = rule_case;
    return *this;
  }
  void incompatible(const char* why) {
    verdict = RuleVerdict::kIncompatible;
    reason = why;
  }
  // Leaves the pair unchanged for the first round of combination (see Tolerance).
  void defer() {
    verdict = RuleVerdict::kNoChange;
    deferred = true;
  }
  void redundantFirst() { verdict = RuleVerdict::kRedundantFirst; }
  void redundantSecond() { verdict = RuleVerdict::kRedundantSecond; }
  // Starts a new alternative and returns it.
  FixedVector<Fundamental, kMaxRuleOutputs>& addAlternative() {
    verdict = RuleVerdict::kReplace;
    alternatives.push_back({});
    return alternatives[alternatives.size() - 1];
  }
};

// a and b arrive in the kinds the rule was registered for.
using RuleFn = void (*)(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                        RuleOutput& out);

}  // namespace relpos
