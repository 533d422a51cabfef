#pragma once
// What the plugin loader checks before it hands a file to dlopen. The dynamic loader trusts the
// headers it maps: a segment that reaches past the end of a truncated file is a SIGBUS inside
// dlopen, not an error. Reading the headers ourselves first turns that into a message.
#include <string>

namespace relpos::plugins {

// Why the file at `path` is not a shared library for this host that dlopen can map safely, in a
// few words ("truncated: segment 2 ends at byte 12345 of a 2000-byte file"), or "" when its ELF
// header, program headers and section header table are all consistent with the file.
std::string elfProblem(const std::string& path);

}  // namespace relpos::plugins
