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
#include <exception>
#include <string>

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
// the virtual rebase, and Branch, which a plugin's matcher appends, its origin).
inline constexpr long kPluginAbiVersion = 5;

// The version with a fingerprint of the shared layouts folded in, so a plugin built against other
// headers is refused even when the version number was not bumped.
constexpr long pluginAbi() {
  return kPluginAbiVersion * 1000000L +
         static_cast<long>((sizeof(Fundamental) * 131 + sizeof(ConstraintSet) * 31 +
                            sizeof(RuleOutput) * 7 + sizeof(Decomposition) * 3 + kManifoldStorage +
                            sizeof(MatchContext) + sizeof(Branch) * 11) %
                           1000000);
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
