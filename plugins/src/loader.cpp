#include "relpos/plugins/loader.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>

#include "elf_check.hpp"
#include "relpos/core/plugin_api.hpp"

#ifndef BOOST_DLL_USE_STD_FS
#define BOOST_DLL_USE_STD_FS
#endif
#include <boost/dll/shared_library.hpp>

namespace relpos::plugins {
namespace fs = std::filesystem;
namespace dll = boost::dll;

namespace {

// Every symbol resolved at load: a plugin calling a function nothing defines is refused by
// dlopen with the symbol's name, instead of killing the process at its first call (lazy binding).
constexpr int kLoadMode = RTLD_NOW | RTLD_LOCAL;

std::string canonical(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path : p.string();
}

bool fail(const std::string& path, const std::string& why, std::string* error) {
  *error = path + ": " + why;
  return false;
}

// Boost.DLL reports a generic error code; dlerror() says what the dynamic loader found wrong
// (a missing dependency, an undefined symbol), after the path we already name.
std::string whyNotLoadable(const std::string& path, const dll::fs::error_code& ec) {
  if (void* h = dlopen(path.c_str(), kLoadMode)) {
    dlclose(h);
    return ec.message();
  }
  const char* why = dlerror();
  if (!why) return ec.message();
  const std::string text = why;
  return text.rfind(path + ": ", 0) == 0 ? text.substr(path.size() + 2) : text;
}

// What is at `path` when it is not a regular file, or "".
std::string notAFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::regular) return "";
  if (st.type() == fs::file_type::directory) return "a directory, not a plugin file";
  if (ec || st.type() == fs::file_type::not_found) return "no such plugin file";
  return "not a regular file";
}

// "6 (layout 0x1a2b3c4d5e6f)": the version and the fingerprint of the shared layouts.
std::string abiText(long abi) {
  char layout[32];
  std::snprintf(layout, sizeof layout, "%#lx", pluginAbiFingerprintOf(abi));
  return std::to_string(pluginAbiVersionOf(abi)) + " (layout " + layout + ")";
}

// Why a plugin answering `abi` is refused.
std::string abiMismatch(long abi) {
  const bool same_version = pluginAbiVersionOf(abi) == kPluginAbiVersion;
  return "built for relpos plugin ABI " + abiText(abi) + ", this relpos has " +
         abiText(pluginAbi()) +
         (same_version ? ": the same version built from headers with other shared layouts" : "") +
         " (rebuild the plugin against this relpos)";
}

}  // namespace

bool loadPlugin(const std::string& path, Registry& registry, std::string* error,
                const LoadOptions& options) {
  const std::string id = canonical(path);
  const auto& loaded = registry.pluginPaths();
  if (std::find(loaded.begin(), loaded.end(), id) != loaded.end()) return true;
  if (registry.frozen())
    return fail(path, "the registry is frozen: load plugins before solving", error);
  if (const std::string why = notAFile(id); !why.empty()) return fail(path, why, error);
  // dlopen maps what the headers say: checked first, a truncated file is a message, not SIGBUS.
  if (const std::string why = elfProblem(id); !why.empty())
    return fail(path, "not a loadable plugin (" + why + ")", error);

  auto lib = std::make_shared<dll::shared_library>();
  dll::fs::error_code ec;
  lib->load(id, static_cast<dll::load_mode::type>(kLoadMode), ec);
  if (ec || !lib->is_loaded())
    return fail(path, "not a loadable plugin (" + whyNotLoadable(id, ec) + ")", error);
  if (!lib->has("relpos_plugin_abi") || !lib->has("relpos_register_plugin"))
    return fail(path,
                "not a relpos plugin: it does not export relpos_plugin_abi and "
                "relpos_register_plugin (end a source file with RELPOS_PLUGIN(...))",
                error);
  long abi = 0;
  try {
    abi = lib->get_alias<PluginAbiFn>("relpos_plugin_abi")();
  } catch (...) {  // not one RELPOS_PLUGIN made: its ABI query is noexcept
    return fail(path, "not a relpos plugin: its relpos_plugin_abi threw", error);
  }
  if (abi != pluginAbi()) return fail(path, abiMismatch(abi), error);

  // Registration is all or nothing: on failure the registry goes back to this copy. The library
  // is kept first, so that the items it registers can record it (MatcherInfo::library).
  Registry before = registry;
  const char* failure = nullptr;
  std::string thrown;
  registry.keepLoaded(id, std::shared_ptr<const void>(lib, lib.get()));
  registry.setOrigin(id, options.allow_override);
  try {
    failure = lib->get_alias<PluginRegisterFn>("relpos_register_plugin")(registry);
  } catch (const std::exception& e) {  // the entry point catches; this is belt and braces
    thrown = e.what();
  } catch (...) {
    thrown = "unknown exception";
  }
  registry.clearOrigin();
  if (failure || !thrown.empty()) {
    const std::string why = failure ? std::string(failure) : thrown;
    registry = std::move(before);
    const bool clash = why.find("already registered") != std::string::npos;
    return fail(path,
                "registration failed: " + why +
                    (clash ? " (pass --allow-override to let the plugin replace it)" : ""),
                error);
  }
  return true;
}

std::vector<std::string> expandPluginPath(const std::string& value) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= value.size()) {
    std::size_t end = value.find(':', start);
    if (end == std::string::npos) end = value.size();
    const std::string entry = value.substr(start, end - start);
    start = end + 1;
    if (entry.empty()) continue;
    std::error_code ec;
    if (fs::is_directory(entry, ec)) {
      std::vector<std::string> files;
      for (const auto& e : fs::directory_iterator(entry, ec))
        if (e.path().extension() == ".so") files.push_back(e.path().string());
      std::sort(files.begin(), files.end());
      out.insert(out.end(), files.begin(), files.end());
    } else {
      out.push_back(entry);
    }
  }
  return out;
}

}  // namespace relpos::plugins
