#pragma once
// A file's whole text, for a batch's JSONL input: mapped read-only when the file is regular, so
// a 100 MB batch costs no copy and no fresh pages (reading it into a string took longer than
// parsing a tenth of its specs); read in chunks otherwise (a pipe).
#include <string>
#include <string_view>

namespace relpos::cli {

class FileText {
 public:
  // Throws UsageError when the file cannot be read.
  explicit FileText(const std::string& path);
  ~FileText();
  FileText(const FileText&) = delete;
  FileText& operator=(const FileText&) = delete;

  std::string_view view() const { return view_; }

 private:
  void* map_ = nullptr;
  std::size_t map_size_ = 0;
  std::string read_;  // the text when it could not be mapped
  std::string_view view_;
};

}  // namespace relpos::cli
