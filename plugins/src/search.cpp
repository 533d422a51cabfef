#include "relpos/plugins/search.hpp"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace relpos::plugins {

std::vector<std::string> pluginFoldersFor(const std::string& program_dir) {
  std::vector<std::string> out;
  if (program_dir.empty()) return out;
  const fs::path here(program_dir);
  // bin/relpos -> lib/relpos/plugins; lib/python3.X/dist-packages/relpos -> lib/relpos/plugins;
  // build/cli/relpos and build/python/relpos -> build/plugins.
  for (const fs::path& p : {here / ".." / "lib" / "relpos" / "plugins",
                            here / ".." / ".." / ".." / "relpos" / "plugins",
                            here / ".." / "plugins", here / ".." / ".." / "plugins"}) {
    std::error_code ec;
    const fs::path dir = fs::weakly_canonical(p, ec);
    if (ec || !fs::is_directory(dir, ec)) continue;
    bool has_plugin = false;  // (the source tree's plugins/ is beside build/ too)
    for (const auto& e : fs::directory_iterator(dir, ec))
      has_plugin = has_plugin || e.path().extension() == ".so";
    if (!has_plugin) continue;
    bool seen = false;
    for (const std::string& d : out) seen = seen || d == dir.string();
    if (!seen) out.push_back(dir.string());
  }
  return out;
}

std::string executableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

std::string findPlugin(const std::string& path, const std::vector<std::string>& folders) {
  std::error_code ec;
  // A path with a folder in it names that file only: a stale path must not load another build.
  if (fs::exists(path, ec) || path.find('/') != std::string::npos) return path;
  const std::string& name = path;
  if (name.empty()) return path;
  for (const std::string& dir : folders)
    for (const std::string& file : {name, name + ".so", "relpos-" + name + ".so"}) {
      const fs::path candidate = fs::path(dir) / file;
      if (fs::is_regular_file(candidate, ec)) return candidate.string();
    }
  return path;
}

std::string bareEntry(const std::string& joined, const std::string& dir) {
  const std::string prefix = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  if (joined.compare(0, prefix.size(), prefix) != 0) return "";
  const std::string entry = joined.substr(prefix.size());
  return entry.find('/') == std::string::npos ? entry : std::string();
}

}  // namespace relpos::plugins
