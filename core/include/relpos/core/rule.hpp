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

// a and b arrive in the kinds the rule was registered for. `context` is RuleInfo::context, passed
// through unchanged (a plugin's own data, so that its rule needs no global; built-in rules ignore
// it).
using RuleFn = void (*)(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                        RuleOutput& out, const void* context);

// One case of a rule family declared once: the value its rule passes to RuleOutput::fire, the
// case's name after "FAMILY/" and its citation. A family lists its cases in a table of these in
// the order of their values (casesInOrder), so that value, name and citation cannot drift apart.
struct RuleCaseRow {
  int value;
  const char* name;      // e.g. "circle" (the case is then "pp+pplane/circle")
  const char* citation;  // e.g. "PMF App. IV Table V, row 4 (d_b < p, d_a = 0)"
};
// Whether row i of `rows` has the value i: the rule's fire(value) then names rows[value].
template <std::size_t N>
constexpr bool casesInOrder(const RuleCaseRow (&rows)[N]) {
  for (std::size_t i = 0; i < N; ++i)
    if (rows[i].value != static_cast<int>(i)) return false;
  return true;
}

}  // namespace relpos
