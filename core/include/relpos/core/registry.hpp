#pragma once
// The one place where constraint types, combination rules and manifold matchers are registered:
// built-ins through explicit register functions, plugins through the same calls. After set-up
// the registry is frozen and read concurrently by any number of solves.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "relpos/core/feature.hpp"
#include "relpos/core/fundamental.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/rule.hpp"
#include "relpos/core/rule_names.hpp"

namespace relpos {

class BranchSink;
struct Solution;
class Registry;

// " (built-in)" or " (plugin PATH)": where an item comes from, for a message about it.
std::string originNote(const std::string& origin);

// --- constraint types -------------------------------------------------------------------------
inline constexpr std::size_t kMaxDecompositionAlternatives = 2;
struct Decomposition {
  // Alternatives (one per orientation for "either"), each a set of fundamental constraints.
  FixedVector<FixedVector<Fundamental, 4>, kMaxDecompositionAlternatives> alternatives;
  // Set when this input is valid but cannot be expressed in fundamental constraints yet.
  const char* unhandled = nullptr;
  FixedVector<Fundamental, 4>& addAlternative() {
    alternatives.push_back({});
    return alternatives[alternatives.size() - 1];
  }
};

// Every registered callback is handed, as its last argument, the `context` its item was
// registered with (nullptr when none): a plugin's own state (e.g. the index of its custom kind)
// lives there instead of in a global, and two registries loading one plugin keep theirs apart.
// Registry::keep() owns such state for as long as the registry (and its copies) live.

// fixed_W is c.fixed placed in world coordinates; c.mobile stays in the mobile frame.
using DecomposeFn = void (*)(const InputConstraint& c, const Feature& fixed_W, SourceMask source,
                             Decomposition& out, const void* context);
// Appends "field: problem" messages for a structurally valid constraint whose values are wrong
// (e.g. "value: negative distance -1 for an unsigned distance").
using CheckFn = void (*)(const InputConstraint& c, std::vector<std::string>& problems,
                         const void* context);
// How far features placed in the world (the fixed one by the fixed pose, the mobile one by a pose
// of a branch) are from meeting c, in units of the tolerance: the larger of the length part over
// tol.length and the angle part over tol.angle (0 when c holds; NaN never: infinity instead). The
// solver checks every branch it returns with it; a type without one is not checked.
using ViolationFn = double (*)(const InputConstraint& c, const Feature& fixed_W,
                               const Feature& mobile_W, const Tolerance& tol, const void* context);

struct FeaturePair {
  FeatureKind fixed, mobile;
};

// What a constraint type's "value" / "min" / "max" measure: the spec reader converts an angle
// from the spec's angle unit (deg → rad) and reads a length as given.
enum class ValueKind : unsigned char { kNone, kLength, kAngle };

// A constraint type declares everything the spec reader needs to read its constraints: the
// reader knows no type by name.
struct ConstraintType {
  std::string name;
  std::string description;
  std::vector<FeaturePair> accepts;
  // Needs "value" or "min"/"max" (implied by a value_kind other than kNone; without one, a plugin's
  // value is a plain number, read as given). A type without a value warns that one is ignored.
  bool takes_value = false;
  ValueKind value_kind = ValueKind::kNone;
  // The optional fields it reads: "orientation" (aligned / opposed / either), and the "parallel"
  // flag on these fixed-mobile feature pairs (distance: line-line). The reader warns that a field
  // a type does not read is ignored.
  bool takes_orientation = true;
  std::vector<FeaturePair> parallel_on;
  CheckFn check = nullptr;
  DecomposeFn decompose = nullptr;
  ViolationFn violation = nullptr;
  const void* context = nullptr;  // handed to every call of check, decompose and violation
  std::string origin = "built-in";
  bool accepts_pair(FeatureKind f, FeatureKind m) const;
  // Runs `check` (when set) on c: an exception from it (plugin code) becomes one more problem,
  // "type: constraint type 'NAME' (plugin PATH) threw in its value check: WHAT", not an unwind
  // through the caller.
  void checkValues(const InputConstraint& c, std::vector<std::string>& problems) const;
};

// --- rules -------------------------------------------------------------------------------------
// One case of a rule: a row (or a group of rows) of a PMF table. The rule function tells which
// case applied (RuleOutput::fire), so rule coverage is counted per case.
struct RuleCase {
  std::string name;      // stable, e.g. "pp+pp/circle"
  std::string citation;  // e.g. "PMF App. IV Table I, row 4"
};

struct RuleInfo {
  std::string name;      // the family, e.g. "pp+pp" (also the case name when there are no cases)
  std::string citation;  // e.g. "PMF App. IV Table I"
  FundamentalKind first, second;
  RuleFn fn = nullptr;
  const void* context = nullptr;  // handed to every call of fn (RuleFn)
  std::vector<RuleCase> cases;
  std::string origin = "built-in";
  // Whether the rule understands ranges (lo < hi); other rules never see a pair with a range.
  bool handles_ranges = false;
  // The name recorded when this rule fires with case `fired` (-1: the rule's own name).
  const std::string& firedName(int fired) const {
    return fired >= 0 && fired < static_cast<int>(cases.size()) ? cases[fired].name : name;
  }
};

// --- manifold matchers -------------------------------------------------------------------------
// A matcher looks at a fully combined constraint set and either appends branches through
// ctx.branches (kMatched), proves the set empty (kInconsistent, with `conflict` and `reason`),
// replaces it by derived sets that the solver combines and matches in turn (ctx.branches.defer,
// kDeferred: e.g. the translational constraints re-anchored once the rotation is known), or
// passes (kNoMatch). When the sink refuses a branch or a set (the solve's max_branches is spent)
// the matcher answers kOverflow. Built-in matchers are never handed a set holding a plugin's
// fundamental kind (FundamentalKind::kCustom): only plugins' matchers know those.
enum class MatchResult : unsigned char { kNoMatch, kMatched, kInconsistent, kOverflow, kDeferred };
struct MatchContext {
  const ConstraintSet& set;
  const Tolerance& tol;
  BranchSink& branches;
  SourceMask conflict = 0;
  const char* reason = "";
};
using MatchFn = MatchResult (*)(MatchContext& ctx, const void* context);

struct ManifoldInfo {
  std::string name;  // manifold type name, e.g. "OneParallel"
  std::string description;
  std::string origin = "built-in";
};
struct MatcherInfo {
  std::string name;
  MatchFn fn = nullptr;
  const void* context = nullptr;  // handed to every call of fn
  std::string origin = "built-in";
  // Set by the registry: the path of the plugin library this matcher comes from, living as long
  // as Registry::loadedLibraries() (what its branches record as Branch::origin); nullptr for a
  // built-in matcher.
  const char* library = nullptr;
};

// --- custom fundamental kinds (plugins) --------------------------------------------------------
// How far pose X_WM is from satisfying f (0 inside), in the units of f's value: what the
// conformance kits sample with.
using ResidualFn = double (*)(const Fundamental& f, const Isometry3d& X_WM, const void* context);
struct CustomKindInfo {
  std::string name;
  std::string description;
  ResidualFn residual = nullptr;
  const void* context = nullptr;  // handed to every call of residual
  std::string origin = "built-in";
};

// --- the numeric stage (docs/spec.md §8) -------------------------------------------------------
// Answers a problem the rules left `unhandled` (library relpos_complete registers one; a plugin
// may register its own). Called by solve() after the rules and the last check (§6.5), only when
// the answer is kUnhandled, with `solution` holding that answer (its message the rules' reason,
// no branches, the rules that fired) and `tol` the problem's tolerance. Returns true when it
// answered: status kSolved with branches — each exact (a closed form) or certified
// (Branch::exact false, Branch::certified its proof) — and `complete` from its proof, or
// kInconsistent only when proven (conflicts and message saying which and why). Returns false
// when it could not: the rules' answer stands (a message it set is added to theirs). Its answer
// goes through the same last check as the rules'. (To run the rules on a part of the problem it
// may call solveConstraintSet, which never calls the fallback; solve() with this registry would
// call it again.)
using FallbackFn = bool (*)(const Problem& problem, const Registry& registry, const Tolerance& tol,
                            Solution& solution, const void* context);
struct FallbackInfo {
  std::string name;  // e.g. "complete"
  FallbackFn fn = nullptr;
  const void* context = nullptr;  // handed to every call of fn
  std::string origin = "built-in";
  // Set by the registry, as MatcherInfo::library: what the fallback's branches record as
  // Branch::origin; nullptr for a built-in one.
  const char* library = nullptr;
};

class Registry {
 public:
  // Each add throws std::invalid_argument on a duplicate name (unless replace is true) or once
  // the registry is frozen.
  void addConstraintType(ConstraintType t, bool replace = false);
  void addRule(RuleInfo r, bool replace = false);
  void addManifold(ManifoldInfo m, bool replace = false);
  void addMatcher(MatcherInfo m, bool replace = false);
  // Registers a fundamental kind of its own for a plugin; returns the index to store in
  // Fundamental::custom (the same index when the name is already registered by this origin).
  std::uint16_t addCustomKind(CustomKindInfo k);
  // Registers the numeric stage (one per registry): throws std::invalid_argument when one is
  // already registered (unless replace, or the origin allows replacing) or fn is null, and
  // std::logic_error once frozen.
  void setFallback(FallbackInfo f, bool replace = false);
  void freeze() { frozen_ = true; }

  // Keeps `state` (a plugin's, for its callbacks' context) as long as this registry and its
  // copies live; returns where it is, to store as an item's `context`.
  template <typename T>
  const T* keep(T state) {
    auto kept = std::make_shared<const T>(std::move(state));
    kept_.push_back(kept);
    return kept.get();
  }

  // While an origin is set (the plugin loader sets the plugin's path), every item added is
  // stamped with it, and `allow_replace` lets it replace an item of the same name. A matcher
  // added then also records the library kept for that path (MatcherInfo::library): the loader
  // keeps the library before it registers the plugin's items.
  void setOrigin(std::string origin, bool allow_replace);
  void clearOrigin();
  // Keeps a loaded plugin library alive as long as this registry and every Solution solved with
  // it (their manifolds' code may live in the library).
  void keepLoaded(const std::string& path, std::shared_ptr<const void> library);
  const std::shared_ptr<const void>& loadedLibraries() const { return libraries_; }
  // The path of the loaded library `origin` names, as a string that lives as long as
  // loadedLibraries() does (so a Solution's branches can name their plugin after the registry is
  // gone); nullptr for built-in items and for an origin no library was kept for.
  const char* libraryPath(const std::string& origin) const;
  const std::vector<std::string>& pluginPaths() const { return plugin_paths_; }
  bool frozen() const { return frozen_; }

  const ConstraintType* constraintType(const std::string& name) const;
  const std::vector<ConstraintType>& constraintTypes() const { return types_; }
  const std::vector<RuleInfo>& rules() const { return rules_; }
  // The names of rules() and their cases, shared with every Solution solved with this registry
  // (Solution::ruleName), so they outlive it.
  const std::shared_ptr<const RuleNames>& ruleNames() const { return rule_names_; }
  const std::vector<ManifoldInfo>& manifolds() const { return manifolds_; }
  const std::vector<MatcherInfo>& matchers() const { return matchers_; }
  const std::vector<CustomKindInfo>& customKinds() const { return custom_kinds_; }
  const CustomKindInfo* customKind(const std::string& name) const;
  // The numeric stage, or nullptr when none is registered.
  const FallbackInfo* fallback() const { return fallback_.fn ? &fallback_ : nullptr; }

  // Rules for an ordered pair of kinds: indices into rules(), with `swapped` telling whether the
  // rule wants the pair in the opposite order. Built once per registration, never scanned.
  struct Entry {
    int rule;
    bool swapped;
  };
  const std::vector<Entry>& rulesFor(FundamentalKind a, FundamentalKind b) const {
    return table_[static_cast<int>(a)][static_cast<int>(b)];
  }

 private:
  void checkOpen() const;
  // One node per loaded library, each holding the previous: copying the head keeps them all.
  // Declared first so it is destroyed last: what is kept below (kept_, and an item's strings)
  // may have been made by a library's code.
  std::shared_ptr<const void> libraries_;
  std::vector<std::shared_ptr<const void>> kept_;
  bool frozen_ = false;
  std::vector<ConstraintType> types_;
  std::vector<RuleInfo> rules_;
  std::vector<ManifoldInfo> manifolds_;
  std::vector<MatcherInfo> matchers_;
  std::vector<CustomKindInfo> custom_kinds_;
  FallbackInfo fallback_;  // fn == nullptr: none
  std::shared_ptr<const RuleNames> rule_names_;
  std::string origin_;                    // empty: built-in
  const char* origin_library_ = nullptr;  // libraryPath(origin_)
  bool allow_replace_ = false;
  std::vector<std::string> plugin_paths_;
  std::array<std::array<std::vector<Entry>, kFundamentalKinds>, kFundamentalKinds> table_;
};

}  // namespace relpos
