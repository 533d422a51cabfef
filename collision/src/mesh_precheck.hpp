#pragma once
// Checks of a mesh file before CGAL reads it. CGAL's OFF and PLY readers trust the counts a file
// states: an OFF header or a face's vertex count, a PLY list's length make them allocate what it
// says (gigabytes, from a few bytes of file), and a negative OFF index is converted to an unsigned
// one (undefined behaviour). Each check walks the file as CGAL will read it and refuses what would
// make CGAL do either; what CGAL refuses safely on its own may pass.
#include <istream>
#include <streambuf>
#include <string>

namespace relpos::collision::detail {

// A read-only stream over text already in memory (std::istringstream would copy it), that knows
// where it is without a system call.
class TextStream : public std::istream {
 public:
  explicit TextStream(const std::string& text) : std::istream(nullptr), buffer_(text) {
    rdbuf(&buffer_);
  }

 private:
  struct Buffer : std::streambuf {
    explicit Buffer(const std::string& text) {
      char* p = const_cast<char*>(text.data());  // only ever read
      setg(p, p, p + text.size());
    }
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
      if (off != 0 || dir != std::ios_base::cur) return pos_type(off_type(-1));
      return pos_type(gptr() - eback());  // tellg
    }
  };
  Buffer buffer_;
};

// "" when CGAL may read `text`, the contents of an .off file; otherwise what is wrong with it.
std::string precheckOff(const std::string& text);

// The same for a .ply file.
std::string precheckPly(const std::string& text);

}  // namespace relpos::collision::detail
