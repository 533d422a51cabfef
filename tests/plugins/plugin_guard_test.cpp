// Plugins whose code throws once loaded: a value check, a decomposition, a rule, a matcher, the
// methods of a manifold. Every one becomes an answer naming the plugin (an `unhandled` solve, a
// problem of the spec, an `unhandled` result line), never an exception out of the solver or the
// writer.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "bad/manifold_throws.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/loader.hpp"
#include "relpos/report/evaluate.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"
#include "test_fallback.hpp"

namespace relpos::test {
namespace {
namespace fs = std::filesystem;

std::string badPlugin(const std::string& name) {
  return RELPOS_BAD_PLUGIN_DIR "/bad-" + name + ".so";
}

// The name the messages give the plugin: its absolute path.
std::string pluginNote(const std::string& name) {
  return "(plugin " + fs::canonical(badPlugin(name)).string() + ")";
}

Registry registryWith(const std::string& name) {
  Registry r;
  registerBuiltins(r);
  std::string error;
  EXPECT_TRUE(plugins::loadPlugin(badPlugin(name), r, &error)) << error;
  r.freeze();
  return r;
}

// A fixed point A and a mobile point P joined by one constraint of `type`.
Problem onePair(const std::string& type, double value = 0.0) {
  Problem p;
  p.addFixedFeature("A", Feature::makePoint(Vector3d(1, 2, 3)))
      .addMobileFeature("P", Feature::makePoint(Vector3d(0, 0, 0)));
  p.addConstraint(type, "A", "P", value);
  p.constraints[0].has_value = true;
  return p;
}

// The solve does not throw, and answers `unhandled` with every piece of `expected` in its message.
void expectUnhandled(const Solution& s, std::initializer_list<std::string> expected) {
  EXPECT_EQ(s.status, Status::kUnhandled) << s.message;
  EXPECT_TRUE(s.branches.empty());
  for (const auto& e : expected) EXPECT_NE(s.message.find(e), std::string::npos) << s.message;
}

TEST(PluginGuards, ADecompositionThatThrows) {
  const Registry r = registryWith("decompose-throws");
  Solution s;
  ASSERT_NO_THROW(s = solve(onePair("explodes-in-decomposition"), r));
  expectUnhandled(s, {"constraint 0: the decomposition of constraint type "
                      "'explodes-in-decomposition' " +
                      pluginNote("decompose-throws") + " threw: the decomposition blew up"});
  ASSERT_NO_THROW(s = solve(onePair("throws-an-int"), r));
  expectUnhandled(
      s, {pluginNote("decompose-throws"), "threw: an exception that is not a std::exception"});
}

TEST(PluginGuards, AValueCheckThatThrows) {
  const Registry r = registryWith("check-throws");
  Solution s;
  ASSERT_NO_THROW(s = solve(onePair("explodes-in-check"), r));
  expectUnhandled(s, {"constraint 0: the value check of constraint type 'explodes-in-check' " +
                      pluginNote("check-throws") + " threw: the value check blew up"});

  // The spec reader runs the check too: the throw is the constraint's problem.
  const std::string spec = R"({"relpos": 1, "name": "x",
    "fixed": {"features": {"A": {"point": [0, 0, 0]}}},
    "mobile": {"features": {"P": {"point": [0, 0, 0]}}},
    "constraints": [{"type": "explodes-in-check", "fixed": "A", "mobile": "P"}]})";
  ParseResult pr;
  ASSERT_NO_THROW(pr = parseSpec(spec, r, "x"));
  EXPECT_FALSE(pr.problem);
  ASSERT_EQ(pr.errors.size(), 1u);
  EXPECT_EQ(pr.errors[0].path, "constraints[0].type");
  EXPECT_EQ(pr.errors[0].message, "constraint type 'explodes-in-check' " +
                                      pluginNote("check-throws") +
                                      " threw in its value check: the value check blew up");
}

TEST(PluginGuards, ARuleThatThrows) {
  Solution s;
  ASSERT_NO_THROW(s = solve(onePair("explodes-in-rule"), registryWith("rule-throws")));
  expectUnhandled(s, {"rule 'explodes:custom+custom' " + pluginNote("rule-throws") +
                      " threw: the rule blew up"});
}

TEST(PluginGuards, AMatcherThatThrows) {
  Solution s;
  ASSERT_NO_THROW(s = solve(onePair("explodes-in-matcher"), registryWith("matcher-throws")));
  expectUnhandled(
      s, {"matcher 'explodes' " + pluginNote("matcher-throws") + " threw: the matcher blew up"});
}

// A plugin's numeric stage (docs/spec.md §8) is stamped with the plugin, and what it throws keeps
// the rules' `unhandled`, naming it.
TEST(PluginGuards, ANumericStageThatThrows) {
  const Registry r = registryWith("fallback-throws");
  ASSERT_NE(r.fallback(), nullptr);
  EXPECT_EQ(r.fallback()->origin, fs::canonical(badPlugin("fallback-throws")).string());
  ASSERT_NE(r.fallback()->library, nullptr);
  EXPECT_EQ(r.fallback()->library, r.fallback()->origin);
  const Problem p = platformProblem(platformPose());
  const Solution rules = solve(p, rulesOnlyRegistry());
  ASSERT_EQ(rules.status, Status::kUnhandled);
  Solution s;
  ASSERT_NO_THROW(s = solve(p, r));
  EXPECT_EQ(s.status, Status::kUnhandled);
  EXPECT_FALSE(s.complete);
  EXPECT_EQ(s.message, rules.message + "; the numeric stage 'explodes-in-fallback' " +
                           pluginNote("fallback-throws") + " threw: the fallback blew up");
}

// What cannot be caught later (an overrun, a null pointer) is checked by the solver right after
// the plugin's matcher made the branch, with the cheap methods that check calls.
TEST(PluginGuards, AManifoldTheWriterCouldNotUse) {
  using namespace manifold_throws;
  const Registry r = registryWith("manifold-throws");
  const std::string from = " from matcher 'bad-manifold' " + pluginNote("manifold-throws");
  const struct {
    Mode mode;
    std::string expected;
  } cases[] = {
      {kTypeNameThrows, "typeName() of manifold '?'" + from + " threw: typeName blew up"},
      {kDofThrows, "dof() of manifold 'Bad'" + from + " threw: dof blew up"},
      {kParameterThrows, "parameter(i) of manifold 'Bad'" + from + " threw: parameter blew up"},
      {kTooManyDof, "manifold 'Bad'" + from + " is unusable: dof() is 7, outside 0..6"},
      {kUnnamedParameter, "manifold 'Bad'" + from + " is unusable: parameter(0) has no name"},
      {kNoManifold, "manifold '?'" + from + " is unusable: a branch without a manifold"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("mode " + std::to_string(c.mode));
    Solution s;
    ASSERT_NO_THROW(s = solve(onePair("bad-manifold", c.mode), r));
    expectUnhandled(s, {c.expected});
  }
}

// The methods that compute run after the solve, in the writer's nearest-pose search and samples:
// what they throw there still gives the line, `unhandled`, naming the plugin.
TEST(PluginGuards, AManifoldThatThrowsWhileTheResultIsWritten) {
  using namespace manifold_throws;
  const Registry r = registryWith("manifold-throws");
  const std::string prefix = "a manifold of plugin " +
                             fs::canonical(badPlugin("manifold-throws")).string() +
                             " threw while writing the result: ";
  const struct {
    Mode mode;
    const char* thrown;
  } cases[] = {
      {kPoseThrows, "pose blew up"},
      {kProjectThrows, "project blew up"},
      {kDescribeThrows, "describe blew up"},
      {kClosedFormParamsThrows, "closedFormParams blew up"},
      {kPoseWithTailThrows, "poseWithTail blew up"},
      {kPoseThrowsAwayFromZero, "pose away from zero blew up"},  // only in the samples
  };
  for (const auto& c : cases) {
    SCOPED_TRACE("mode " + std::to_string(c.mode));
    const Problem p = onePair("bad-manifold", c.mode);
    const Solution s = solve(p, r);
    if (c.mode == kPoseThrows) {
      // The solver's own check of every branch evaluates a pose: caught there, named there.
      EXPECT_EQ(s.status, Status::kUnhandled);
      // The rules' reason first; what the numeric stage said of it may follow (§8.1).
      const std::string expected = "a manifold of plugin " +
                                   fs::canonical(badPlugin("manifold-throws")).string() +
                                   " threw while checking its branches: " + c.thrown;
      EXPECT_EQ(s.message.substr(0, expected.size()), expected);
      continue;
    }
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    ReportOptions options;
    options.samples = 3;
    std::string line;
    ASSERT_NO_THROW(writeResultLine(p, s, options, line));
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["status"], "unhandled");
    EXPECT_EQ(j["branches"].size(), 0u);
    EXPECT_TRUE(j["best"].is_null());
    EXPECT_EQ(j["message"], prefix + c.thrown);
    Report report;
    ASSERT_NO_THROW(evaluate(p, s, options, report));
    EXPECT_EQ(report.status, Status::kUnhandled);
  }
}

// A matcher that answers "no match" but leaves a branch behind: the branch is checked all the
// same, under the name of the matcher that made it.
TEST(PluginGuards, ABranchLeftBehindByAMatcherThatPassed) {
  Solution s;
  ASSERT_NO_THROW(s = solve(onePair("bad-manifold", manifold_throws::kStrayBranch),
                            registryWith("manifold-throws")));
  expectUnhandled(s, {"manifold 'Bad' from matcher 'bad-manifold-stray' " +
                      pluginNote("manifold-throws") + " is unusable: dof() is 7, outside 0..6"});
}

TEST(PluginGuards, APluginBranchRecordsItsPlugin) {
  const Registry r = registryWith("manifold-throws");
  const Solution s = solve(onePair("bad-manifold", manifold_throws::kWellBehaved), r);
  ASSERT_EQ(s.status, Status::kSolved) << s.message;
  ASSERT_EQ(s.branches.size(), 1u);
  ASSERT_NE(s.branches[0].origin, nullptr);
  EXPECT_EQ(s.branches[0].origin, fs::canonical(badPlugin("manifold-throws")).string());
  // A built-in matcher's branch names none.
  Problem p = onePair("coincident");
  const Solution builtin = solve(p, r);
  ASSERT_EQ(builtin.status, Status::kSolved) << builtin.message;
  EXPECT_EQ(builtin.branches[0].origin, nullptr);
}

}  // namespace
}  // namespace relpos::test
