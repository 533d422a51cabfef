#pragma once
// How the relpos command fails: each kind of failure has its exit code and its one message.
#include <stdexcept>

namespace relpos::cli {

inline constexpr int kExitOk = 0, kExitInternal = 1, kExitInvalid = 2;
// Batch interrupted by Ctrl-C (the results written so far are complete lines, in order).
inline constexpr int kExitInterrupted = 130;

// The command line itself is wrong: its message, the usage text, exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Input the user can fix (an -o that cannot be written, a folder given as a spec): one line,
// exit 2, nothing written.
struct InvalidInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writing the results failed (a full disk, an I/O error): one line naming the file and the
// reason, exit 1. What was left behind is complete (solve: nothing; batch: whole lines).
struct WriteFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace relpos::cli
