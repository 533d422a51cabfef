#pragma once
// A problem found in the input, named by where it is: the spec reader's errors and warnings, and
// the collision scene's (a mesh that cannot be read). Plain data: core reads no files.
#include <string>

namespace relpos {

struct Diagnostic {
  std::string path;     // JSON path, e.g. "constraints[3].mobile"; "" for the whole document
  std::string message;  // what is wrong
};

}  // namespace relpos
