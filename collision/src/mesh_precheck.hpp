#pragma once
// Checks of a mesh file before CGAL reads it. CGAL's OFF and PLY readers trust the counts a file
// states: an OFF header or a face's vertex count, a PLY list's length make them allocate what it
// says (gigabytes, from a few bytes of file), and a negative OFF index is converted to an unsigned
// one (undefined behaviour). Each check walks the file as CGAL will read it and refuses what would
// make CGAL do either; what CGAL refuses safely on its own may pass.
#include <string>

namespace relpos::collision::detail {

// "" when CGAL may read `text`, the contents of an .off file; otherwise what is wrong with it.
std::string precheckOff(const std::string& text);

// The same for a .ply file.
std::string precheckPly(const std::string& text);

}  // namespace relpos::collision::detail
