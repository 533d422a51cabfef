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

// `path` itself when it names a file (or when nothing else does: loading it reports that);
// otherwise the first of NAME, NAME.so, relpos-NAME.so in `folders`, NAME being the path's file
// name.
std::string findPlugin(const std::string& path, const std::vector<std::string>& folders);

}  // namespace relpos::plugins
