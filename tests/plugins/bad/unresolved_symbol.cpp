// A plugin that calls a function no library defines. Loaded lazily, the dynamic loader would only
// notice at the first call, inside registration, and kill the process (exit 127, "symbol lookup
// error"); the loader binds every symbol at load, so dlopen refuses it with the symbol's name.
#include "relpos/core/plugin_api.hpp"

extern "C" int relpos_test_function_nothing_defines(int);

namespace unresolved_symbol {
void registerAll(relpos::Registry&) { (void)relpos_test_function_nothing_defines(1); }
}  // namespace unresolved_symbol

RELPOS_PLUGIN(unresolved_symbol::registerAll)
