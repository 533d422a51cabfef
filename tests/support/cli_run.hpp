#pragma once
// Running the relpos command as a user runs it, for the CLI tests: each test in its own scratch
// folder, stdout and stderr captured.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_config.hpp"

namespace relpos::test {

namespace fs = std::filesystem;

// The inputs the CLI tests run most: the worked example and 100 generated grasp and weld lines.
inline const std::string kExample = RELPOS_DATA_DIR "/examples/pmf-simple-example.json";
inline const std::string kBatchSample = RELPOS_DATA_DIR "/batch/grasp-and-weld-100.jsonl";

struct CmdResult {
  int code;  // the exit status; -1 when a signal ended the process
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A folder of this test's own (made on first use): the process id and the suite in its name, as
// ctest runs the CLI and plugin CLI binaries side by side.
inline fs::path scratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  fs::path d = fs::temp_directory_path() / ("relpos_cli_test_" + std::to_string(::getpid()) + "_" +
                                            info->test_suite_name() + "_" + info->name());
  fs::create_directories(d);
  return d;
}

// Runs a shell command line, its output captured in the scratch folder.
inline CmdResult runShell(const std::string& command) {
  const fs::path d = scratchDir();
  // Braces: the redirections take in every command of a list ("a & b; c").
  const std::string cmd =
      "{ " + command + "; } >" + (d / "out").string() + " 2>" + (d / "err").string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(d / "out"), slurp(d / "err")};
}

// `relpos ARGS`, after an optional prefix (a variable, prlimit, setpriv).
inline CmdResult run(const std::string& args, const std::string& prefix = "") {
  return runShell(prefix + std::string(RELPOS_EXE) + " " + args);
}

inline fs::path writeSpec(const std::string& name, const std::string& text) {
  fs::path p = scratchDir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

}  // namespace relpos::test
