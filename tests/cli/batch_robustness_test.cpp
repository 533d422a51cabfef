// A batch never loses a finished line: a line that is not a spec, a spec that makes a worker
// throw, names that are not UTF-8 — each becomes its own result line and the batch goes on.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "json_lines.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

const std::string kReplacementCharacter = "\xEF\xBF\xBD";  // U+FFFD

TEST(CliBatchRobustness, MalformedLinesWithAnyBytesAreInvalidLines) {
  const std::string bad[] = {
      "{\"relpos\": 1, \"name\": \xC3\xA9}",       // valid UTF-8 (é), malformed JSON
      "{\"relpos\": 1, \"name\": \"\xFF\"}",       // not UTF-8
      "{\"relpos\": 1, \"name\": \"a\x01\x7F\"}",  // control characters
      "{\"relpos\": 1, \"na\xE2\x82"};             // a UTF-8 sequence cut short at the end
  std::string text = slurp(kBatchSample);
  for (const auto& line : bad) text += line + "\n";
  text += slurp(kBatchSample).substr(0, slurp(kBatchSample).find('\n') + 1);
  const fs::path in = writeSpec("mixed.jsonl", text), out = scratchDir() / "results.jsonl";
  const CmdResult r = run("batch " + in.string() + " --jobs 2 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = parsedLines(slurp(out));
  ASSERT_EQ(lines.size(), 105u);
  for (std::size_t i = 0; i < 100; ++i) EXPECT_NE(lines[i]["status"], "invalid") << i;
  for (std::size_t i = 100; i < 104; ++i) {
    EXPECT_EQ(lines[i]["status"], "invalid") << i;
    EXPECT_TRUE(lines[i]["name"].is_string()) << lines[i];
    const std::string source = in.string() + ":" + std::to_string(i + 1) + ": ";
    EXPECT_EQ(lines[i]["message"].get<std::string>().rfind(source, 0), 0u) << lines[i];
  }
  EXPECT_EQ(lines[100]["name"], "mixed:101");  // no readable name: STEM:LINE
  EXPECT_EQ(lines[104]["status"], "solved");
}

TEST(CliBatchRobustness, AWorkerThatThrowsBecomesThatSpecsLine) {
  nlohmann::json spec = nlohmann::json::parse(slurp(kExample));
  const std::string good = spec.dump();
  spec["name"] = "explodes-when-decomposed";
  // Q on Q: a type of the bad plugin whose decomposition throws (tests/plugins/bad).
  spec["constraints"][2]["type"] = "explodes-in-decomposition";
  const fs::path in = writeSpec("throws.jsonl", good + "\n" + spec.dump() + "\n" + good + "\n");
  const CmdResult r = run("batch " + in.string() +
                          " --jobs 2 --plugin " RELPOS_BAD_PLUGIN_DIR "/bad-decompose-throws.so");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = parsedLines(r.out);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0]["status"], "solved");
  EXPECT_EQ(lines[1]["name"], "explodes-when-decomposed");
  EXPECT_EQ(lines[1]["status"], "unhandled");
  EXPECT_NE(lines[1]["message"].get<std::string>().find("the decomposition blew up"),
            std::string::npos)
      << lines[1];
  EXPECT_EQ(lines[2]["status"], "solved");
  EXPECT_NE(r.err.find("unhandled 1"), std::string::npos) << r.err;
}

TEST(CliBatchRobustness, AFileNameThatIsNotUtf8GivesAUtf8Name) {
  const fs::path d = scratchDir() / "specs";
  fs::create_directories(d);
  nlohmann::json spec = nlohmann::json::parse(slurp(kExample));
  spec.erase("name");  // the default name is the file's stem: here the byte 0xFF
  std::ofstream(d / "\xFF.json") << spec.dump();
  const CmdResult solved = run("solve '" + (d / "\xFF.json").string() + "'");
  ASSERT_EQ(solved.code, 0) << solved.err;
  const nlohmann::json result = nlohmann::json::parse(solved.out);  // throws on invalid UTF-8
  EXPECT_EQ(result["name"], kReplacementCharacter);
  EXPECT_EQ(result["status"], "solved");
  const CmdResult batch = run("batch " + d.string());
  ASSERT_EQ(batch.code, 0) << batch.err;
  const auto lines = parsedLines(batch.out);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0]["name"], kReplacementCharacter);
  // Invalid, the same file's line is UTF-8 too (its message quotes the path).
  std::ofstream(d / "\xFF.json") << "{\"relpos\": 1}";
  const auto invalid = parsedLines(run("batch " + d.string()).out);
  ASSERT_EQ(invalid.size(), 1u);
  EXPECT_EQ(invalid[0]["status"], "invalid");
  EXPECT_EQ(invalid[0]["name"], kReplacementCharacter);
}

TEST(CliBatchRobustness, ADiagnosticNamingAFileWithANewlineStaysOneLine) {
  const fs::path file = writeSpec("two\nlines.json", "{\"relpos\": 1, \"fixed\": [}");
  const CmdResult r = run("solve '" + file.string() + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("two\\nlines.json: malformed JSON"), std::string::npos) << r.err;
}

TEST(CliSolve, AFolderIsNotASpec) {
  const fs::path d = scratchDir() / "a-folder.json";
  fs::create_directories(d);
  const CmdResult r = run("solve " + d.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, d.string() + ": is a directory, not a spec file\n");
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace relpos::test
