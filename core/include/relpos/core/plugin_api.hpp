#pragma once
// The plugin ABI. A plugin is a shared library linked against relpos_core that defines a function
// `void registerAll(relpos::Registry&)` adding its constraint types, custom kinds, rules,
// manifolds and matchers through the same Registry calls the built-ins use, and ends one source
// file with
//
//   RELPOS_PLUGIN(my_plugin::registerAll)
//
// which exports two Boost.DLL aliases: `relpos_plugin_abi` (checked by the loader before anything
// else) and `relpos_register_plugin` (the entry point). No exception crosses the boundary: the
// entry point catches whatever registration throws (even while copying its message) and hands
// the loader the message. Later calls into the plugin's items (checks, decompositions, rules,
// matchers, its manifolds' methods) are guarded by relpos itself: what they throw becomes an
// `unhandled` answer naming the plugin.
#include <cstdint>
#include <exception>
#include <string>

#include "relpos/core/abi_fingerprint.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/core/solution.hpp"

#ifndef BOOST_DLL_USE_STD_FS
#define BOOST_DLL_USE_STD_FS
#endif
#include <boost/dll/alias.hpp>

namespace relpos {

// Bumped whenever a type a plugin shares with relpos changes incompatibly (2: Manifold gained
// the virtual closedFormParams/poseWithTail, which moves every later vtable slot; 3: the built-in
// SeparableManifold and RadialGraspManifold a plugin may build gained members; 4: Manifold gained
// the virtual rebase, and Branch, which a plugin's matcher appends, its origin; 6: issue 14 —
// every registered callback takes a `const void* context` (DecomposeFn, CheckFn, ViolationFn,
// MatchFn, ResidualFn, RuleFn) beside a `context` member of its item; matchers append through a
// BranchSink (MatchContext::branches replaces `out`, `defer` and `solver`); MatcherInfo records
// its library; Solution::rules holds RuleCaseIds named by a shared RuleNames table;
// ConstraintType declares its value kind and fields; Manifold's built-in shapes gained a kind
// tag; the fingerprint below replaced a sum of sizes; 7: issue 15 — Branch gained `exact` and
// `certified` (a Certificate), Solution `complete`, Registry the numeric stage's hook
// (setFallback: FallbackInfo, FallbackFn); 8: issue 18 — Manifold gained the virtual
// searchDistance, a new last slot that a plugin built before it lacks; 9: issue 18 — and
// nearestRotation after it; 10: issue 18 — and nearestArc after that; 11: issue 18 — and
// rotationCoupling after that).
inline constexpr long kPluginAbiVersion = 11;

// A fingerprint of every struct a plugin shares with relpos, member by member (offset, size,
// alignment), and of every callback's signature: a plugin built against headers that differ in
// any of them is refused even when the version was not bumped. A member added to one of these
// structs belongs in this list. (Virtual functions are not in it: a change to Manifold's bumps
// the version.)
constexpr std::uint64_t pluginLayoutFingerprint() {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Winvalid-offsetof"
  return abi::hash(
      // vocabulary
      RELPOS_ABI_TYPE(Vector3d), RELPOS_ABI_TYPE(Isometry3d), RELPOS_ABI_TYPE(Feature),
      RELPOS_ABI_MEMBER(Feature, kind), RELPOS_ABI_MEMBER(Feature, point),
      RELPOS_ABI_MEMBER(Feature, direction), RELPOS_ABI_MEMBER(Feature, radius),
      RELPOS_ABI_TYPE(InputConstraint), RELPOS_ABI_MEMBER(InputConstraint, type),
      RELPOS_ABI_MEMBER(InputConstraint, id), RELPOS_ABI_MEMBER(InputConstraint, fixed),
      RELPOS_ABI_MEMBER(InputConstraint, mobile), RELPOS_ABI_MEMBER(InputConstraint, fixed_name),
      RELPOS_ABI_MEMBER(InputConstraint, mobile_name),
      RELPOS_ABI_MEMBER(InputConstraint, has_value), RELPOS_ABI_MEMBER(InputConstraint, value),
      RELPOS_ABI_MEMBER(InputConstraint, min), RELPOS_ABI_MEMBER(InputConstraint, max),
      RELPOS_ABI_MEMBER(InputConstraint, orientation), RELPOS_ABI_MEMBER(InputConstraint, parallel),
      RELPOS_ABI_TYPE(Fundamental), RELPOS_ABI_MEMBER(Fundamental, kind),
      RELPOS_ABI_MEMBER(Fundamental, point_side), RELPOS_ABI_MEMBER(Fundamental, p),
      RELPOS_ABI_MEMBER(Fundamental, q), RELPOS_ABI_MEMBER(Fundamental, d),
      RELPOS_ABI_MEMBER(Fundamental, u), RELPOS_ABI_MEMBER(Fundamental, lo),
      RELPOS_ABI_MEMBER(Fundamental, hi), RELPOS_ABI_MEMBER(Fundamental, err),
      RELPOS_ABI_MEMBER(Fundamental, sources), RELPOS_ABI_MEMBER(Fundamental, id),
      RELPOS_ABI_MEMBER(Fundamental, custom), RELPOS_ABI_TYPE(ConstraintSet),
      RELPOS_ABI_MEMBER(ConstraintSet, translational), RELPOS_ABI_MEMBER(ConstraintSet, rotational),
      RELPOS_ABI_MEMBER(ConstraintSet, tested), RELPOS_ABI_MEMBER(ConstraintSet, dropped_redundant),
      RELPOS_ABI_MEMBER(ConstraintSet, next_id), RELPOS_ABI_MEMBER(ConstraintSet, overflow),
      RELPOS_ABI_MEMBER(ConstraintSet, revolve), RELPOS_ABI_MEMBER(ConstraintSet, revolve_point),
      RELPOS_ABI_MEMBER(ConstraintSet, revolve_axis), RELPOS_ABI_MEMBER(ConstraintSet, slack),
      RELPOS_ABI_TYPE(Tolerance), RELPOS_ABI_MEMBER(Tolerance, length),
      RELPOS_ABI_MEMBER(Tolerance, angle), RELPOS_ABI_MEMBER(Tolerance, max_amplification),
      // what callbacks fill in
      RELPOS_ABI_TYPE(Decomposition), RELPOS_ABI_MEMBER(Decomposition, alternatives),
      RELPOS_ABI_MEMBER(Decomposition, unhandled), RELPOS_ABI_TYPE(RuleOutput),
      RELPOS_ABI_MEMBER(RuleOutput, verdict), RELPOS_ABI_MEMBER(RuleOutput, reason),
      RELPOS_ABI_MEMBER(RuleOutput, fired), RELPOS_ABI_MEMBER(RuleOutput, deferred),
      RELPOS_ABI_MEMBER(RuleOutput, alternatives), RELPOS_ABI_TYPE(MatchContext),
      RELPOS_ABI_MEMBER(MatchContext, set), RELPOS_ABI_MEMBER(MatchContext, tol),
      RELPOS_ABI_MEMBER(MatchContext, branches), RELPOS_ABI_MEMBER(MatchContext, conflict),
      RELPOS_ABI_MEMBER(MatchContext, reason), RELPOS_ABI_TYPE(BranchSink), RELPOS_ABI_TYPE(Branch),
      RELPOS_ABI_MEMBER(Branch, manifold), RELPOS_ABI_MEMBER(Branch, sources),
      RELPOS_ABI_MEMBER(Branch, origin), RELPOS_ABI_MEMBER(Branch, exact),
      RELPOS_ABI_MEMBER(Branch, certified), RELPOS_ABI_TYPE(Certificate),
      RELPOS_ABI_MEMBER(Certificate, radius), RELPOS_ABI_MEMBER(Certificate, angle),
      RELPOS_ABI_TYPE(ManifoldHolder), kManifoldStorage, kMaxDof, RELPOS_ABI_TYPE(Parameter),
      RELPOS_ABI_MEMBER(Parameter, name), RELPOS_ABI_MEMBER(Parameter, kind),
      RELPOS_ABI_MEMBER(Parameter, min), RELPOS_ABI_MEMBER(Parameter, max),
      RELPOS_ABI_MEMBER(Parameter, periodic), RELPOS_ABI_TYPE(Solution),
      RELPOS_ABI_MEMBER(Solution, libraries), RELPOS_ABI_MEMBER(Solution, rule_names),
      RELPOS_ABI_MEMBER(Solution, status), RELPOS_ABI_MEMBER(Solution, complete),
      RELPOS_ABI_MEMBER(Solution, isolated_complete), RELPOS_ABI_MEMBER(Solution, message),
      RELPOS_ABI_MEMBER(Solution, branches), RELPOS_ABI_MEMBER(Solution, conflicts),
      RELPOS_ABI_MEMBER(Solution, redundant), RELPOS_ABI_MEMBER(Solution, rules),
      RELPOS_ABI_MEMBER(Solution, solve_us), RELPOS_ABI_TYPE(RuleCaseId),
      // what a plugin registers
      RELPOS_ABI_TYPE(FeaturePair), RELPOS_ABI_TYPE(ConstraintType),
      RELPOS_ABI_MEMBER(ConstraintType, name), RELPOS_ABI_MEMBER(ConstraintType, description),
      RELPOS_ABI_MEMBER(ConstraintType, accepts), RELPOS_ABI_MEMBER(ConstraintType, takes_value),
      RELPOS_ABI_MEMBER(ConstraintType, value_kind),
      RELPOS_ABI_MEMBER(ConstraintType, takes_orientation),
      RELPOS_ABI_MEMBER(ConstraintType, parallel_on), RELPOS_ABI_MEMBER(ConstraintType, check),
      RELPOS_ABI_MEMBER(ConstraintType, decompose), RELPOS_ABI_MEMBER(ConstraintType, violation),
      RELPOS_ABI_MEMBER(ConstraintType, context), RELPOS_ABI_MEMBER(ConstraintType, origin),
      RELPOS_ABI_TYPE(RuleCase), RELPOS_ABI_MEMBER(RuleCase, name),
      RELPOS_ABI_MEMBER(RuleCase, citation), RELPOS_ABI_TYPE(RuleInfo),
      RELPOS_ABI_MEMBER(RuleInfo, name), RELPOS_ABI_MEMBER(RuleInfo, citation),
      RELPOS_ABI_MEMBER(RuleInfo, first), RELPOS_ABI_MEMBER(RuleInfo, second),
      RELPOS_ABI_MEMBER(RuleInfo, fn), RELPOS_ABI_MEMBER(RuleInfo, cases),
      RELPOS_ABI_MEMBER(RuleInfo, origin), RELPOS_ABI_MEMBER(RuleInfo, handles_ranges),
      RELPOS_ABI_MEMBER(RuleInfo, context), RELPOS_ABI_TYPE(ManifoldInfo),
      RELPOS_ABI_MEMBER(ManifoldInfo, name), RELPOS_ABI_MEMBER(ManifoldInfo, description),
      RELPOS_ABI_MEMBER(ManifoldInfo, origin), RELPOS_ABI_TYPE(MatcherInfo),
      RELPOS_ABI_MEMBER(MatcherInfo, name), RELPOS_ABI_MEMBER(MatcherInfo, fn),
      RELPOS_ABI_MEMBER(MatcherInfo, context), RELPOS_ABI_MEMBER(MatcherInfo, origin),
      RELPOS_ABI_MEMBER(MatcherInfo, library), RELPOS_ABI_TYPE(CustomKindInfo),
      RELPOS_ABI_MEMBER(CustomKindInfo, name), RELPOS_ABI_MEMBER(CustomKindInfo, description),
      RELPOS_ABI_MEMBER(CustomKindInfo, residual), RELPOS_ABI_MEMBER(CustomKindInfo, context),
      RELPOS_ABI_MEMBER(CustomKindInfo, origin), RELPOS_ABI_TYPE(FallbackInfo),
      RELPOS_ABI_MEMBER(FallbackInfo, name), RELPOS_ABI_MEMBER(FallbackInfo, fn),
      RELPOS_ABI_MEMBER(FallbackInfo, context), RELPOS_ABI_MEMBER(FallbackInfo, origin),
      RELPOS_ABI_MEMBER(FallbackInfo, library), RELPOS_ABI_TYPE(Registry),
      // the callbacks
      abi::Signature<DecomposeFn>::value, abi::Signature<CheckFn>::value,
      abi::Signature<ViolationFn>::value, abi::Signature<RuleFn>::value,
      abi::Signature<MatchFn>::value, abi::Signature<ResidualFn>::value,
      abi::Signature<FallbackFn>::value);
#pragma GCC diagnostic pop
}

// What a plugin's relpos_plugin_abi answers: the version in the bits from 48 up, the
// fingerprint's low 48 bits below (a long is 64 bits wide on every platform a plugin loads on).
inline constexpr int kPluginAbiFingerprintBits = 48;
static_assert(sizeof(long) == 8, "the plugin ABI answer needs a 64-bit long");
constexpr long pluginAbi() {
  return static_cast<long>(
      (static_cast<std::uint64_t>(kPluginAbiVersion) << kPluginAbiFingerprintBits) |
      (pluginLayoutFingerprint() & ((std::uint64_t{1} << kPluginAbiFingerprintBits) - 1)));
}
// The version and the fingerprint of an answer (before version 6 an answer was VERSION·10⁶ plus
// a sum of sizes: its version is read off that).
constexpr long pluginAbiVersionOf(long abi) {
  return abi >> kPluginAbiFingerprintBits ? abi >> kPluginAbiFingerprintBits : abi / 1000000;
}
constexpr long pluginAbiFingerprintOf(long abi) {
  return abi >> kPluginAbiFingerprintBits ? abi & ((1L << kPluginAbiFingerprintBits) - 1)
                                          : abi % 1000000;
}

using PluginAbiFn = long();
// Returns nullptr, or the message of what went wrong (valid until the next call).
using PluginRegisterFn = const char*(Registry&);

}  // namespace relpos

#define RELPOS_PLUGIN(register_function)                                  \
  namespace relpos_plugin_entry {                                         \
  inline long abi() noexcept { return ::relpos::pluginAbi(); }            \
  inline const char* registerAll(::relpos::Registry& registry) noexcept { \
    static std::string error;                                             \
    try {                                                                 \
      register_function(registry);                                        \
      return nullptr;                                                     \
    } catch (const std::exception& e) {                                   \
      try {                                                               \
        error = e.what();                                                 \
      } catch (...) {                                                     \
        return "an exception whose message could not be copied";          \
      }                                                                   \
    } catch (...) {                                                       \
      return "an exception that is not a std::exception";                 \
    }                                                                     \
    return error.c_str();                                                 \
  }                                                                       \
  }                                                                       \
  BOOST_DLL_ALIAS(relpos_plugin_entry::abi, relpos_plugin_abi)            \
  BOOST_DLL_ALIAS(relpos_plugin_entry::registerAll, relpos_register_plugin)
