// A plugin built against another relpos: its ABI query answers a version this relpos refuses.
#include "relpos/core/plugin_api.hpp"

namespace wrong_abi {
// The next version, with this relpos's layouts.
long abi() { return relpos::pluginAbi() + (1L << relpos::kPluginAbiFingerprintBits); }
const char* registerAll(relpos::Registry&) noexcept { return nullptr; }
}  // namespace wrong_abi

BOOST_DLL_ALIAS(wrong_abi::abi, relpos_plugin_abi)
BOOST_DLL_ALIAS(wrong_abi::registerAll, relpos_register_plugin)
