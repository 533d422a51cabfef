// The plugins a command loads before it reads its specs.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "file_text.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/io/text.hpp"
#include "relpos/plugins/loader.hpp"
#include "relpos/plugins/search.hpp"

namespace fs = std::filesystem;

namespace relpos::cli {

namespace {

// Where a plugin named by no file was looked for, for its message.
std::string notFoundByName(const std::string& path, const std::vector<std::string>& folders) {
  if (folders.empty()) return "";
  std::string where;
  for (const std::string& f : folders) where += (where.empty() ? "" : ", ") + f;
  const std::string name = fs::path(path).filename().string();
  return " (nor is " + name + ", " + name + ".so or relpos-" + name + ".so in " + where + ")";
}

}  // namespace

// Loads, in order, the plugins of RELPOS_PLUGIN_PATH, of --plugin, and of the "plugins" lists of
// the specs the command will read. The first failure is one line on stderr; false then.
bool loadPlugins(const std::string& cmd, const Args& a, Registry& reg) {
  struct Item {
    std::string path, where;  // where: what named it, for the message
    // a plugin named without a folder (a spec's entry joined to the spec's folder): found by
    // name beside relpos when no such file is there (a path that names no file is not)
    std::string name;
  };
  auto specItem = [](const std::string& path, const std::string& dir, std::string where) {
    return Item{path, std::move(where), relpos::plugins::bareEntry(path, dir)};
  };
  auto bare = [](const std::string& p) {
    return p.find('/') == std::string::npos ? p : std::string();
  };
  std::vector<Item> items;
  if (const char* env = std::getenv("RELPOS_PLUGIN_PATH"))
    for (const auto& p : relpos::plugins::expandPluginPath(env))
      items.push_back({p, "RELPOS_PLUGIN_PATH: ", bare(p)});
  for (const auto& p : a.plugins) items.push_back({p, "", bare(p)});
  std::vector<std::string> specs;
  if ((cmd == "solve" || cmd == "export") && a.positional.size() == 1) specs = a.positional;
  const bool batch = cmd == "batch" && a.positional.size() == 1;
  if ((cmd == "table" || (cmd == "rules" && a.coverage) ||
       (batch && fs::is_directory(a.positional[0]))) &&
      !a.positional.empty())
    specs = specFiles(a.positional);
  else if (batch && fs::is_regular_file(a.positional[0])) {
    // A JSONL file: each line's list, relative to the file's folder. One search of the whole
    // text first: most batches name no plugin, and then no line needs looking at.
    // The lines are views into the mapped text (as the batch reads them), numbered alike.
    const FileText text(a.positional[0]);
    const std::string dir = fs::path(a.positional[0]).parent_path().string();
    const std::string_view all =
        relpos::mentionsPlugins(text.view()) ? text.view() : std::string_view();
    std::size_t n = 0;
    for (std::size_t at = 0; at < all.size(); ++n) {
      const std::size_t end = std::min(all.find('\n', at), all.size());
      const auto paths = relpos::specPluginPathsInText(all.substr(at, end - at), dir);
      for (std::size_t i = 0; i < paths.size(); ++i)  // "FILE:LINE: plugins[i]: ", one line
        items.push_back(specItem(
            paths[i], dir,
            relpos::formatDiagnostic(a.positional[0] + ":" + std::to_string(n + 1),
                                     {"plugins[" + std::to_string(i) + "]", ""})));
      at = end + 1;
    }
  }
  for (const auto& spec : specs) {
    const auto paths = relpos::specPluginPaths(spec);
    for (std::size_t i = 0; i < paths.size(); ++i)
      items.push_back(specItem(paths[i], fs::path(spec).parent_path().string(),
                               spec + ": plugins[" + std::to_string(i) + "]: "));
  }
  relpos::plugins::LoadOptions options;
  options.allow_override = a.allow_override;
  // A path that names no file is looked for by name beside relpos (docs/spec.md §4.1).
  const std::vector<std::string> folders =
      relpos::plugins::pluginFoldersFor(relpos::plugins::executableDir());
  for (const auto& item : items) {
    std::string error;
    const bool missing = !fs::exists(item.path);
    const std::string path = missing && !item.name.empty()
                                 ? relpos::plugins::findPlugin(item.name, folders)
                                 : item.path;
    if (!relpos::plugins::loadPlugin(path, reg, &error, options)) {
      if (missing && !item.name.empty()) error += notFoundByName(item.name, folders);
      std::cerr << "relpos: " << oneLine(item.where + error) << "\n";
      return false;
    }
  }
  return true;
}

}  // namespace relpos::cli
