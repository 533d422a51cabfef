#pragma once
// Finding a plugin by name (issue 17): `--plugin symmetric` or `"plugins": ["symmetric"]` finds
// the example plugin installed beside relpos (PREFIX/lib/relpos/plugins/relpos-symmetric.so), or
// the one in the build tree, without its full path. docs/spec.md §4.1.
#include <string>
#include <vector>

namespace relpos::plugins {

// The folders a plugin is looked for in, relative to the folder of the program loading it (the
// relpos command's bin/ or build/cli/, or the Python package's folder): PREFIX/lib/relpos/plugins
// for an installed program, BUILD/plugins for one in the build tree; the ones that hold a .so.
std::vector<std::string> pluginFoldersFor(const std::string& program_dir);

// The folder of the running executable ("" when it cannot be told).
std::string executableDir();

// `path` itself when it names a file or has a folder in it (a stale path must not load another
// build; loading it reports the missing file); otherwise, a bare NAME, the first of NAME, NAME.so,
// relpos-NAME.so in `folders` (NAME itself when none is there).
std::string findPlugin(const std::string& path, const std::vector<std::string>& folders);

// The entry of a spec's "plugins" list as it was written, when it was a bare name: `joined` is
// the entry joined to the spec's folder `dir` (specPluginPaths); "" when the entry had a folder
// in it (or was absolute).
std::string bareEntry(const std::string& joined, const std::string& dir);

}  // namespace relpos::plugins
