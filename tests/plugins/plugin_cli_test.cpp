// Bad plugins through the relpos command, as a user meets them: a file dlopen cannot map safely
// or whose symbols do not resolve is one line and exit 2 before anything runs; plugin code that
// throws once loaded is an answer (an `unhandled` result, an `invalid` line) naming the plugin,
// in `solve` and in every line of `batch` — never a signal, never exit 1, never a lost line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bad/manifold_throws.hpp"
#include "cli_run.hpp"
#include "json_lines.hpp"
#include "test_config.hpp"

namespace {
using nlohmann::json;
using relpos::test::CmdResult;
using relpos::test::parsedLines;
using relpos::test::run;
using relpos::test::scratchDir;
using relpos::test::slurp;
namespace fs = std::filesystem;

fs::path writeFile(const std::string& name, const std::string& text) {
  return relpos::test::writeSpec(name, text);
}

std::string badPlugin(const std::string& name) {
  return RELPOS_BAD_PLUGIN_DIR "/bad-" + name + ".so";
}
std::string canonicalBad(const std::string& name) {
  return fs::canonical(badPlugin(name)).string();
}

const std::string kExample = RELPOS_DATA_DIR "/examples/pmf-simple-example.json";

// One line: a fixed point A and a mobile point P joined by a constraint of `type`.
std::string onePairSpec(const std::string& type, int value = -1) {
  json c = {{"type", type}, {"fixed", "A"}, {"mobile", "P"}};
  if (value >= 0) c["value"] = value;
  json spec = {{"relpos", 1},
               {"name", "bad-" + type},
               {"fixed", {{"features", {{"A", {{"point", {1, 2, 3}}}}}}}},
               {"mobile", {{"features", {{"P", {{"point", {0, 0, 0}}}}}}}},
               {"constraints", {c}}};
  return spec.dump();
}

void expectOneLine(const CmdResult& r, const std::string& start, const std::string& expected) {
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind(start, 0), 0u) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// Files dlopen would crash on (SIGBUS on the cut one) or that would end the process at their first
// call (exit 127 on the unresolved symbol): refused by `--plugin` before anything runs.
TEST(PluginCli, FilesThatCannotBeLoadedSafelyAreOneLineAndExitTwo) {
  const std::string plugin = slurp(RELPOS_PLUGIN_DIR "/relpos-helical.so");
  const fs::path cut = writeFile("truncated.so", plugin.substr(0, 2000));
  const fs::path empty = writeFile("empty.so", "");
  const fs::path text = writeFile("text.so", "plain text\n");
  const fs::path dir = scratchDir() / "folder.so";
  fs::create_directories(dir);
  const fs::path batch = writeFile("one.jsonl", json::parse(slurp(kExample)).dump() + "\n");
  const struct {
    std::string path, expected;
  } cases[] = {
      {cut.string(), "not a loadable plugin (truncated: segment "},
      {empty.string(), "not a loadable plugin (an empty file)"},
      {text.string(), "not a loadable plugin (not an ELF file"},
      {dir.string(), "a directory, not a plugin file"},
      {badPlugin("unresolved-symbol"),
       "not a loadable plugin (undefined symbol: relpos_test_function_nothing_defines"},
  };
  for (const auto& c : cases) {
    for (const std::string& cmd : {"solve " + kExample, "batch " + batch.string()}) {
      SCOPED_TRACE(cmd + " --plugin " + c.path);
      expectOneLine(run(cmd + " --plugin " + c.path), "relpos: " + c.path + ": ", c.expected);
    }
  }
}

struct Throwing {
  std::string plugin, type;
  int value;
  std::string expected;  // in the message, after the plugin's path
};
const Throwing kThrowing[] = {
    {"decompose-throws", "explodes-in-decomposition", -1, ") threw: the decomposition blew up"},
    {"rule-throws", "explodes-in-rule", -1, ") threw: the rule blew up"},
    {"matcher-throws", "explodes-in-matcher", -1, ") threw: the matcher blew up"},
    {"manifold-throws", "bad-manifold", manifold_throws::kDescribeThrows,
     " threw while writing the result: describe blew up"},
    {"manifold-throws", "bad-manifold", manifold_throws::kTooManyDof,
     ") is unusable: dof() is 7, outside 0..6"},
    // Passes the solver's check at θ = 0; the samples the writer draws are elsewhere.
    {"manifold-throws", "bad-manifold", manifold_throws::kPoseThrowsAwayFromZero,
     " threw while writing the result: pose away from zero blew up"},
};

TEST(PluginCli, SolveAnswersUnhandledWhenPluginCodeThrows) {
  for (const auto& t : kThrowing) {
    SCOPED_TRACE(t.plugin + " " + t.type);
    const fs::path spec = writeFile("spec.json", onePairSpec(t.type, t.value));
    const CmdResult r =
        run("solve " + spec.string() + " --samples 2 --plugin " + badPlugin(t.plugin));
    ASSERT_EQ(r.code, 0) << r.err;
    const json j = json::parse(r.out);
    EXPECT_EQ(j["status"], "unhandled");
    EXPECT_TRUE(j["branches"].empty());
    EXPECT_NE(j["message"].get<std::string>().find(canonicalBad(t.plugin) + t.expected),
              std::string::npos)
        << j["message"];
  }
}

// Every line is written, in order; the bad one says what happened.
TEST(PluginCli, BatchWritesEveryLineWhenPluginCodeThrows) {
  const std::string good = json::parse(slurp(kExample)).dump();
  for (const auto& t : kThrowing) {
    SCOPED_TRACE(t.plugin + " " + t.type);
    const fs::path in =
        writeFile("in.jsonl", good + "\n" + onePairSpec(t.type, t.value) + "\n" + good + "\n");
    const CmdResult r =
        run("batch " + in.string() + " --samples 2 --jobs 2 --plugin " + badPlugin(t.plugin));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto out = parsedLines(r.out);
    ASSERT_EQ(out.size(), 3u) << r.out;
    EXPECT_EQ(out[0]["status"], "solved");
    EXPECT_EQ(out[1]["status"], "unhandled");
    EXPECT_NE(out[1]["message"].get<std::string>().find(canonicalBad(t.plugin) + t.expected),
              std::string::npos)
        << out[1]["message"];
    EXPECT_EQ(out[2]["status"], "solved");
  }
}

// The spec reader runs a type's value check: what it throws is the constraint's problem.
TEST(PluginCli, AValueCheckThatThrowsIsTheSpecsProblem) {
  const std::string plugin = " --plugin " + badPlugin("check-throws");
  const std::string expected = "constraints[0].type: constraint type 'explodes-in-check' (plugin " +
                               canonicalBad("check-throws") +
                               ") threw in its value check: the value check blew up";
  const fs::path spec = writeFile("check.json", onePairSpec("explodes-in-check"));
  expectOneLine(run("solve " + spec.string() + plugin), spec.string() + ": ", expected);

  const std::string good = json::parse(slurp(kExample)).dump();
  const fs::path in =
      writeFile("in.jsonl", good + "\n" + onePairSpec("explodes-in-check") + "\n" + good + "\n");
  const CmdResult r = run("batch " + in.string() + plugin);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto out = parsedLines(r.out);
  ASSERT_EQ(out.size(), 3u) << r.out;
  EXPECT_EQ(out[1]["status"], "invalid");
  EXPECT_NE(out[1]["message"].get<std::string>().find(expected), std::string::npos)
      << out[1]["message"];
  EXPECT_EQ(out[2]["status"], "solved");
}

// The collision filter samples the branch after the result was written: a manifold that throws
// only there still gives a result (solve used to exit 1).
TEST(PluginCli, AManifoldThatThrowsWhileFilteringCollisions) {
  json spec = json::parse(onePairSpec("bad-manifold", manifold_throws::kPoseThrowsAwayFromZero));
  const std::string meshes = RELPOS_DATA_DIR "/collision/meshes/";
  spec["fixed"]["mesh"] = meshes + "table.off";
  spec["mobile"]["mesh"] = meshes + "part.off";
  const fs::path file = writeFile("collide.json", spec.dump());
  const CmdResult r =
      run("solve " + file.string() + " --collision --plugin " + badPlugin("manifold-throws"));
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["status"], "unhandled");
  EXPECT_TRUE(j["branches"].empty());
  EXPECT_EQ(j["collision_free_branches"], 0);
  EXPECT_NE(j["message"].get<std::string>().find(
                canonicalBad("manifold-throws") +
                " threw while filtering collisions: pose away from zero blew up"),
            std::string::npos)
      << j["message"];
}

// The same guard holds in table and batch (it lives in relpos::evaluate, which every command
// calls): table counts no free branch and goes on, batch writes the spec's line as unhandled
// "while filtering collisions" (not "internal error") and the next spec is still solved.
TEST(PluginCli, AManifoldThatThrowsWhileFilteringCollisionsInTableAndBatch) {
  json spec = json::parse(onePairSpec("bad-manifold", manifold_throws::kPoseThrowsAwayFromZero));
  const std::string meshes = RELPOS_DATA_DIR "/collision/meshes/";
  spec["fixed"]["mesh"] = meshes + "table.off";
  spec["mobile"]["mesh"] = meshes + "part.off";
  const std::string plugin = " --plugin " + badPlugin("manifold-throws");
  const std::string thrown = canonicalBad("manifold-throws") +
                             " threw while filtering collisions: pose away from zero blew up";

  const fs::path file = writeFile("collide-table.json", spec.dump());
  const CmdResult t = run("table " + file.string() + " --repeat 1 --collision" + plugin);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("bad-manifold"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find(" 0 invalid"), std::string::npos) << t.out;

  json good = json::parse(slurp(kExample));
  good["fixed"]["mesh"] = meshes + "table.off";
  good["mobile"]["mesh"] = meshes + "part.off";
  const fs::path in = writeFile("collide.jsonl", spec.dump() + "\n" + good.dump() + "\n");
  const CmdResult b = run("batch " + in.string() + " --collision" + plugin);
  ASSERT_EQ(b.code, 0) << b.err;
  const auto out = parsedLines(b.out);
  ASSERT_EQ(out.size(), 2u) << b.out;
  EXPECT_EQ(out[0]["status"], "unhandled");
  EXPECT_TRUE(out[0]["branches"].empty());
  EXPECT_EQ(out[0]["collision_free_branches"], 0);
  EXPECT_NE(out[0]["message"].get<std::string>().find(thrown), std::string::npos)
      << out[0]["message"];
  EXPECT_EQ(out[1]["status"], "solved") << out[1];
  EXPECT_TRUE(out[1].contains("collision_free_branches")) << out[1];
}

}  // namespace
