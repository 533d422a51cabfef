// Where results go (-o): refused before any work when it cannot be written or is an input;
// written whole or not at all by solve, in complete lines by batch, even on a full disk.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cli_run.hpp"
#include "json_lines.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

int lineCount(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

std::set<std::string> filesIn(const fs::path& d) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(d)) names.insert(e.path().filename().string());
  return names;
}

// root ignores permissions: a read-only folder is tested as nobody.
std::string asUnprivileged() {
  return ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
}

TEST(CliOutput, UnwritableOutputIsOneLineAndExitTwoInEveryCommand) {
  const fs::path d = scratchDir();
  fs::create_directories(d / "read-only");
  fs::permissions(d / "read-only", fs::perms::owner_read | fs::perms::owner_exec |
                                       fs::perms::group_read | fs::perms::group_exec |
                                       fs::perms::others_read | fs::perms::others_exec);
  fs::create_directories(d / "folder");
  std::ofstream(d / "plain-file") << "a file, not a folder";
  struct Case {
    std::string out, prefix, says;
  };
  const std::vector<Case> cases = {
      {(d / "missing" / "out.json").string(), "", "no such directory"},
      {(d / "folder").string(), "", "is a directory"},
      {(d / "plain-file" / "out.json").string(), "", "is not a directory"},
      {(d / "read-only" / "out.json").string(), asUnprivileged(), "Permission denied"},
      {"''", "", "an empty path"}};
  for (const std::string& cmd : {"solve " + kExample, "batch " + kBatchSample}) {
    for (const Case& c : cases) {
      const CmdResult r = run(cmd + " -o " + c.out, c.prefix);
      EXPECT_EQ(r.code, 2) << cmd << " -o " << c.out << "\n" << r.err;
      EXPECT_EQ(lineCount(r.err), 1) << r.err;
      EXPECT_EQ(r.err.rfind("relpos: -o", 0), 0u) << r.err;
      EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
    EXPECT_FALSE(fs::exists(d / "missing"));
    EXPECT_TRUE(fs::is_empty(d / "read-only"));
    EXPECT_TRUE(fs::is_empty(d / "folder"));  // no DIR.tmp, nothing inside
    EXPECT_EQ(filesIn(d),
              (std::set<std::string>{"read-only", "folder", "plain-file", "out", "err"}));
  }
  // The commands that write to stdout only say so.
  const CmdResult table = run("table " + kExample + " -o " + (d / "t.txt").string());
  EXPECT_EQ(table.code, 2);
  EXPECT_EQ(lineCount(table.err), 1) << table.err;
  EXPECT_FALSE(fs::exists(d / "t.txt"));
}

TEST(CliOutput, BatchRefusesToWriteOverItsInput) {
  const fs::path d = scratchDir();
  fs::create_directories(d / "sub");
  const fs::path in = d / "in.jsonl";
  fs::copy_file(kBatchSample, in, fs::copy_options::overwrite_existing);
  fs::create_symlink(in, d / "link.jsonl");
  fs::create_hard_link(in, d / "hard.jsonl");
  const std::string before = slurp(in);
  for (const fs::path& out :
       {in, d / "sub" / ".." / "in.jsonl", d / "link.jsonl", d / "hard.jsonl"}) {
    const CmdResult r = run("batch " + in.string() + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << out << "\n" << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("is the input"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(in), before) << out;
  }
  // A folder's spec files are its inputs too.
  fs::create_directories(d / "specs");
  fs::copy_file(kExample, d / "specs" / "a.json");
  const std::string spec = slurp(d / "specs" / "a.json");
  const CmdResult r =
      run("batch " + (d / "specs").string() + " -o " + (d / "specs" / "a.json").string());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(slurp(d / "specs" / "a.json"), spec);
  // And solve's spec.
  const CmdResult s = run("solve " + (d / "specs" / "a.json").string() + " -o " +
                          (d / "specs" / "." / "a.json").string());
  EXPECT_EQ(s.code, 2) << s.err;
  EXPECT_EQ(slurp(d / "specs" / "a.json"), spec);
}

// RLIMIT_FSIZE stands in for a full disk: a write past the limit fails with EFBIG (relpos ignores
// SIGXFSZ, which would otherwise kill it mid-line).
std::string fileSizeLimit(std::size_t bytes) {
  return "prlimit --fsize=" + std::to_string(bytes) + " ";
}

TEST(CliOutput, BatchOnAFullDiskKeepsCompleteLinesAndSaysWhy) {
  const fs::path d = scratchDir();
  std::string many;
  const std::string sample = slurp(kBatchSample);
  for (int k = 0; k < 30; ++k) many += sample;  // 3,000 specs, several MB of results
  const fs::path in = writeSpec("many.jsonl", many), out = d / "results.jsonl";
  const std::size_t limit = 300000;
  const CmdResult r =
      run("batch " + in.string() + " --jobs 2 -o " + out.string(), fileSizeLimit(limit));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("relpos: " + out.string() + ": cannot write: " + std::strerror(EFBIG), 0),
            0u)
      << r.err;
  const std::string text = slurp(out);
  ASSERT_FALSE(text.empty());
  EXPECT_LE(text.size(), limit);
  EXPECT_EQ(text.back(), '\n');
  const auto lines = parsedLines(text);
  std::istringstream specs(many);
  std::string spec;
  for (std::size_t i = 0; i < lines.size() && std::getline(specs, spec); ++i)
    ASSERT_EQ(lines[i]["name"], nlohmann::json::parse(spec)["name"]) << i;
  // The message names the file and the reason (here: no space at all).
  const CmdResult full = run("batch " + kBatchSample + " -o /dev/full");
  EXPECT_EQ(full.code, 1);
  EXPECT_EQ(
      full.err.rfind(std::string("relpos: /dev/full: cannot write: ") + std::strerror(ENOSPC), 0),
      0u)
      << full.err;
  EXPECT_EQ(lineCount(full.err), 1) << full.err;
  const CmdResult stdout_full =
      runShell(std::string(RELPOS_EXE) + " batch " + kBatchSample + " >/dev/full");
  EXPECT_EQ(stdout_full.code, 1);
  EXPECT_EQ(stdout_full.err.rfind(
                std::string("relpos: standard output: cannot write: ") + std::strerror(ENOSPC), 0),
            0u)
      << stdout_full.err;
}

TEST(CliOutput, SolveOnAFullDiskLeavesNothingBehind) {
  const fs::path d = scratchDir() / "target";
  fs::create_directories(d);
  const fs::path out = d / "result.json";
  // The limit is per file: 400 bytes hold the message on stderr, not the result (1.3 KB).
  const CmdResult r = run("solve " + kExample + " -o " + out.string(), fileSizeLimit(400));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(lineCount(r.err), 1) << r.err;
  EXPECT_EQ(r.err, "relpos: " + out.string() + ": cannot write: " + std::strerror(EFBIG) + "\n");
  EXPECT_TRUE(fs::is_empty(d));
  // A result already there stays as it was.
  std::ofstream(out) << "the previous result";
  EXPECT_EQ(run("solve " + kExample + " -o " + out.string(), fileSizeLimit(400)).code, 1);
  EXPECT_EQ(slurp(out), "the previous result");
  EXPECT_EQ(filesIn(d), std::set<std::string>{"result.json"});
}

TEST(CliOutput, SolveWritesAUniqueTemporaryFileAndRenamesIt) {
  const fs::path d = scratchDir() / "target";
  fs::create_directories(d);
  const fs::path out = d / "result.json";
  // A file of the user's that happens to have the name a fixed temporary name would take.
  std::ofstream(d / "result.json.tmp") << "precious";
  const CmdResult r = run("solve " + kExample + " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(out))["status"], "solved");
  EXPECT_EQ(slurp(d / "result.json.tmp"), "precious");
  EXPECT_EQ(filesIn(d), (std::set<std::string>{"result.json", "result.json.tmp"}));
  // Four solves at once to the same -o: each renames its own file; one complete result remains.
  std::string together = "fail=0; ";
  for (int k = 0; k < 4; ++k)
    together += std::string(RELPOS_EXE) + " solve " + kExample + " -o " + out.string() + " & p" +
                std::to_string(k) + "=$!; ";
  for (int k = 0; k < 4; ++k) together += "wait $p" + std::to_string(k) + " || fail=1; ";
  EXPECT_EQ(runShell(together + "exit $fail").code, 0);
  EXPECT_EQ(nlohmann::json::parse(slurp(out))["status"], "solved");
  EXPECT_EQ(filesIn(d), (std::set<std::string>{"result.json", "result.json.tmp"}));
  // A link stays a link: what it points to is replaced.
  fs::create_symlink("real.json", d / "link.json");
  std::ofstream(d / "real.json") << "old";
  ASSERT_EQ(run("solve " + kExample + " -o " + (d / "link.json").string()).code, 0);
  EXPECT_TRUE(fs::is_symlink(d / "link.json"));
  EXPECT_EQ(nlohmann::json::parse(slurp(d / "real.json"))["status"], "solved");
  // Something that is not a regular file (a FIFO here) is written, not replaced.
  ASSERT_EQ(::mkfifo((d / "fifo").c_str(), 0644), 0) << std::strerror(errno);
  const CmdResult piped =
      runShell("cat " + (d / "fifo").string() + " & " + RELPOS_EXE + " solve " + kExample + " -o " +
               (d / "fifo").string() + "; status=$?; wait; exit $status");
  EXPECT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(nlohmann::json::parse(piped.out)["status"], "solved");
  struct stat st {};
  ASSERT_EQ(::lstat((d / "fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

}  // namespace
}  // namespace relpos::test
