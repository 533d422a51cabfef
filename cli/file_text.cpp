#include "file_text.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "cli.hpp"

namespace relpos::cli {

FileText::FileText(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw UsageError("cannot read '" + path + "'");
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
    map_size_ = static_cast<std::size_t>(st.st_size);
    // MAP_POPULATE: the whole file is read anyway; one fault-in beats one fault per page.
    map_ = ::mmap(nullptr, map_size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (map_ == MAP_FAILED) map_ = nullptr;
  }
  ::close(fd);
  if (map_ != nullptr) {
    view_ = std::string_view(static_cast<const char*>(map_), map_size_);
    return;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + path + "'");
  read_ = readAll(in);
  view_ = read_;
}

FileText::~FileText() {
  if (map_ != nullptr) ::munmap(map_, map_size_);
}

}  // namespace relpos::cli
