#pragma once
// Where results go with -o. The path is checked before anything is solved or opened for writing;
// writing it leaves the whole result or nothing (solve), or complete lines (batch).
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace relpos::cli {

// How a command writes its -o file.
enum class OutputMode {
  kReplace,  // solve: a temporary file beside the target, renamed over it once complete
  kStream,   // batch: the file itself, line after line (what an interruption leaves is useful)
};

// Throws InvalidInput when `out` cannot be the -o of a command that reads `inputs`: a folder, a
// path in a missing folder or in one that cannot be written, or one of the inputs (compared by
// device and inode, so links and other spellings of the same path are caught).
void checkOutput(const std::string& out, const std::vector<std::string>& inputs, OutputMode mode);

// solve -o: `path` holds all of `text` afterwards, or what it held before. A regular file (or a
// new one) is replaced by a unique temporary file written beside it, flushed and renamed over it
// (a symbolic link stays a link: its target is replaced); anything else (/dev/stdout, a FIFO) is
// written directly. Throws InvalidInput for what the user can fix (permissions), WriteFailed for
// the rest (a full disk); the temporary file is removed either way.
void replaceFile(const std::string& path, std::string_view text);

// batch's output: whole lines written straight to a file descriptor, so that a failed write is
// known at once with its reason, and the file can be cut back to its last complete line.
class LineSink {
 public:
  LineSink();  // standard output
  // Creates or truncates `path`; throws InvalidInput or WriteFailed when it cannot.
  explicit LineSink(const std::string& path);
  ~LineSink();
  LineSink(const LineSink&) = delete;
  LineSink& operator=(const LineSink&) = delete;

  // Writes `count` lines, each ending in '\n'. False when the system refused: error() then says
  // why, and a regular file is cut back to the end of the last complete line.
  bool write(std::string_view lines, std::size_t count);
  // Closes a file it opened; false (error() says why) when the system reports a late failure.
  bool close();
  const std::string& error() const { return error_; }

 private:
  void fail(int err);

  int fd_;
  bool owned_;
  std::string name_;          // for messages: the path, or "standard output"
  bool truncatable_ = false;  // a regular file: a partial line can be cut off
  off_t start_ = 0;           // where the first line went
  std::uint64_t bytes_ = 0;   // written in complete lines
  std::uint64_t lines_ = 0;
  std::string error_;
};

}  // namespace relpos::cli
