#include "output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "errors.hpp"

namespace relpos::cli {
namespace {
namespace fs = std::filesystem;

std::string inQuotes(const std::string& path) { return "'" + path + "'"; }

// Whether a failed open, create or rename is the user's to fix (a missing folder, permissions, a
// read-only file system): exit 2. The rest (a full disk, an I/O error) is exit 1.
bool usersToFix(int err) {
  switch (err) {
    case EACCES:
    case EPERM:
    case EROFS:
    case ENOENT:
    case ENOTDIR:
    case EISDIR:
    case ELOOP:
    case ENAMETOOLONG:
    case ETXTBSY:
      return true;
    default:
      return false;
  }
}

// (Callers read errno before they build the message: an allocation may change it.)
[[noreturn]] void throwFor(int err, const std::string& message) {
  const std::string text = message + ": " + std::strerror(err);
  if (usersToFix(err)) throw InvalidInput(text);
  throw WriteFailed(text);
}

// The folder a new file at `path` goes into ("." for a bare name).
std::string folderOf(const std::string& path) {
  const std::string dir = fs::path(path).parent_path().string();
  return dir.empty() ? "." : dir;
}

// Writes all of text, through partial writes and signals; false with errno set on failure.
// Writes all of text (a write may take part of it, or be interrupted); false with errno set when
// the output refuses, *written then saying how much of it went out.
bool writeAll(int fd, std::string_view text, std::size_t* written = nullptr) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (written) *written = done;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  if (written) *written = done;
  return true;
}

// Holds back Ctrl-C and termination while a temporary file exists, so that it is always renamed
// or removed; a signal that came meanwhile is delivered at the end.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t held;
    sigemptyset(&held);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&held, s);
    ::sigprocmask(SIG_BLOCK, &held, &previous_);
  }
  ~SignalsHeld() { ::sigprocmask(SIG_SETMASK, &previous_, nullptr); }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t previous_;
};

// The permissions a file created by open(…, 0666) would get.
mode_t newFileMode() {
  const mode_t mask = ::umask(0);  // the only way to read it; solve is single-threaded here
  ::umask(mask);
  return 0666 & ~mask;
}

// Writes text into a file that is not a regular file (a device, a FIFO): nothing to replace.
void writeInPlace(const std::string& path, std::string_view text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    throwFor(err, "-o " + inQuotes(path) + ": cannot open");
  }
  bool ok = writeAll(fd, text);
  int err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) throwFor(err, path + ": cannot write");
}

}  // namespace

void checkOutput(const std::string& out, const std::vector<std::string>& inputs, OutputMode mode) {
  const std::string option = "-o " + inQuotes(out);
  std::string folder;
  struct stat st {};
  if (::stat(out.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw InvalidInput(option + ": is a directory (name a file)");
    for (const auto& in : inputs) {
      struct stat si {};
      if (::stat(in.c_str(), &si) == 0 && si.st_dev == st.st_dev && si.st_ino == st.st_ino)
        throw InvalidInput(option + ": is the input " + inQuotes(in) +
                           " (writing would destroy it while it is read)");
    }
    if (mode == OutputMode::kStream || !S_ISREG(st.st_mode)) {
      // Written in place: the file itself must be writable.
      if (::access(out.c_str(), W_OK) != 0) {
        const int err = errno;
        throwFor(err, option + ": cannot write");
      }
      return;
    }
    folder = folderOf(fs::canonical(out).string());  // where the temporary file will go
  } else {
    const int err = errno;
    if (err != ENOENT && err != ENOTDIR) throwFor(err, option);
    folder = folderOf(out);
  }
  struct stat sf {};
  if (::stat(folder.c_str(), &sf) != 0) {
    const int err = errno;
    if (err == ENOENT) throw InvalidInput(option + ": no such directory " + inQuotes(folder));
    throwFor(err, option + ": " + inQuotes(folder));
  }
  if (!S_ISDIR(sf.st_mode))
    throw InvalidInput(option + ": " + inQuotes(folder) + " is not a directory");
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    const int err = errno;
    throwFor(err, option + ": cannot write in " + inQuotes(folder));
  }
}

void replaceFile(const std::string& path, std::string_view text) {
  struct stat st {};
  const bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode)) {
    writeInPlace(path, text);
    return;
  }
  // A link's target is what gets replaced; the link stays.
  const std::string target = exists ? fs::canonical(path).string() : path;
  const std::string folder = folderOf(target);
  // A hidden name derived from the target's, unique to this process (mkstemp): two solves to the
  // same -o never share it, and a user's own `OUT.tmp` is left alone.
  std::string temporary =
      folder + "/." + fs::path(target).filename().string().substr(0, 200) + ".XXXXXX";
  const mode_t mode = exists ? (st.st_mode & 07777) : newFileMode();
  SignalsHeld held;
  int fd = ::mkostemp(temporary.data(), O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    throwFor(err, "-o " + inQuotes(path) + ": cannot create a file in " + inQuotes(folder));
  }
  const auto fail = [&](int err) {
    if (fd >= 0) ::close(fd);
    ::unlink(temporary.c_str());
    throwFor(err, path + ": cannot write");
  };
  if (!writeAll(fd, text) || ::fchmod(fd, mode) != 0 || ::fsync(fd) != 0) fail(errno);
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0 || ::rename(temporary.c_str(), target.c_str()) != 0) fail(errno);
}

LineSink::LineSink() : fd_(STDOUT_FILENO), owned_(false), name_("standard output") {
  struct stat st {};
  truncatable_ = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
  if (truncatable_) {
    // Appending (>>): the lines go at the end, wherever the offset is now.
    const int flags = ::fcntl(fd_, F_GETFL);
    start_ = ::lseek(fd_, 0, flags >= 0 && (flags & O_APPEND) ? SEEK_END : SEEK_CUR);
    truncatable_ = start_ >= 0;
  }
}

LineSink::LineSink(const std::string& path) : owned_(true), name_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    const int err = errno;
    throwFor(err, "-o " + inQuotes(path) + ": cannot open");
  }
  struct stat st {};
  truncatable_ = ::fstat(fd_, &st) == 0 && S_ISREG(st.st_mode);
}

LineSink::~LineSink() {
  if (owned_ && fd_ >= 0) ::close(fd_);
}

bool LineSink::write(std::string_view lines, std::size_t count) {
  if (!error_.empty()) return false;
  std::size_t done = 0;
  if (!writeAll(fd_, lines, &done)) {
    // The lines that made it whole are kept: up to the last '\n' written.
    const int err = errno;
    const std::size_t whole = lines.substr(0, done).rfind('\n') + 1;  // 0 when none
    bytes_ += whole;
    lines_ += static_cast<std::size_t>(std::count(lines.begin(), lines.begin() + whole, '\n'));
    fail(err);
    return false;
  }
  bytes_ += lines.size();
  lines_ += count;
  return true;
}

bool LineSink::close() {
  if (!owned_ || fd_ < 0) return error_.empty();
  const int closed = ::close(fd_);
  const int err = errno;
  fd_ = -1;
  if (closed != 0 && error_.empty()) {
    error_ = name_ + ": cannot write: " + std::strerror(err);
    return false;
  }
  return error_.empty();
}

void LineSink::fail(int err) {
  error_ = name_ + ": cannot write: " + std::strerror(err) + " (after " + std::to_string(lines_) +
           " complete result lines)";
  // A write that failed half-way left part of a line: cut it off, so that every line the file
  // holds is a whole result.
  if (truncatable_ && ::ftruncate(fd_, start_ + static_cast<off_t>(bytes_)) != 0)
    error_ += "; cutting off the partial line failed: " + std::string(std::strerror(errno));
}

}  // namespace relpos::cli
