#pragma once
// Loading plugins (shared libraries exporting RELPOS_PLUGIN, see relpos/core/plugin_api.hpp) into
// a Registry before it is frozen.
#include <string>
#include <vector>

#include "relpos/core/registry.hpp"

namespace relpos::plugins {

struct LoadOptions {
  // Let the plugin replace items of the same name (built-in or from an earlier plugin).
  bool allow_override = false;
};

// Loads the plugin at `path` into `registry`: checks its ABI, runs its entry point with every item
// stamped with the path as its origin, and keeps the library loaded for as long as the registry
// and the solutions it produces live. A path already loaded into this registry is skipped. On
// failure returns false with one line in `error` ("PATH: what went wrong") and leaves the
// registry exactly as it was.
bool loadPlugin(const std::string& path, Registry& registry, std::string* error,
                const LoadOptions& options = {});

// The plugin files named by a RELPOS_PLUGIN_PATH value: colon-separated files or folders, a folder
// giving its *.so files in name order. Empty entries are skipped; missing ones are returned as
// they are (loading them reports the problem).
std::vector<std::string> expandPluginPath(const std::string& value);

}  // namespace relpos::plugins
