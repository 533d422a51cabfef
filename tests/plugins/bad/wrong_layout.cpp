// A plugin built against headers of this ABI version whose shared structs differ (a member
// added without a version bump): its fingerprint differs, and this relpos refuses it.
#include "relpos/core/plugin_api.hpp"

namespace wrong_layout {
long abi() { return relpos::pluginAbi() ^ 1L; }  // one bit of the fingerprint flipped
const char* registerAll(relpos::Registry&) noexcept { return nullptr; }
}  // namespace wrong_layout

BOOST_DLL_ALIAS(wrong_layout::abi, relpos_plugin_abi)
BOOST_DLL_ALIAS(wrong_layout::registerAll, relpos_register_plugin)
