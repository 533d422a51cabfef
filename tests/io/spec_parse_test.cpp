// Spec parsing: every form of docs/spec.md §1 parses to the right values, and every kind of bad
// input gives an error naming the JSON path and the problem.
#include <gtest/gtest.h>

#include <fstream>

#include "io_test_helpers.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

const char* kBase = R"({
  "relpos": 1,
  "fixed": {"features": {
    "K": {"line": {"point": [0, 0, 3], "direction": [0, 2, 0]}},
    "Pl": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 5]}},
    "C": {"cylinder": {"point": [1, 0, 0], "direction": [0, 0, 1], "radius": 0.5}},
    "Q": {"point": [-2, 0, 3]}}},
  "mobile": {"name": "gripper", "features": {
    "tcp": {"point": [0, 5, 3]}, "palm": {"plane": {"point": [0, 0, 0], "normal": [1, 0, 0]}},
    "ax": {"line": {"point": [0, 0, 0], "direction": [1, 0, 0]}}}},
  "constraints": [ CONSTRAINTS ]
})";

std::string spec(const std::string& constraints, const char* base = kBase) {
  std::string s = base;
  s.replace(s.find("CONSTRAINTS"), 11, constraints);
  return s;
}

// Exactly one error, at `path`, whose message contains `needle`.
void expectError(const std::string& text, const std::string& path, const std::string& needle) {
  ParseResult r = parse(text);
  EXPECT_FALSE(r.problem.has_value());
  ASSERT_FALSE(r.errors.empty()) << "no error for " << text;
  bool found = false;
  std::string all;
  for (const auto& e : r.errors) {
    all += e.path + ": " + e.message + "\n";
    found = found || (e.path == path && e.message.find(needle) != std::string::npos);
  }
  EXPECT_TRUE(found) << "wanted '" << path << ": ..." << needle << "...', got:\n" << all;
}

TEST(SpecParse, ValidSpecParses) {
  ParseResult r = parse(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})"));
  ASSERT_TRUE(r.problem) << r.errors.front().message;
  EXPECT_EQ(r.problem->name, "t");
  EXPECT_EQ(r.problem->mobile.name, "gripper");
  ASSERT_EQ(r.problem->constraints.size(), 1u);
  // Directions are normalised.
  EXPECT_NEAR(r.problem->constraints[0].fixed.direction.norm(), 1.0, 1e-15);
}

TEST(SpecParse, CylinderAxisIsALine) {
  ParseResult r = parse(spec(R"({"type": "coincident", "fixed": "C.axis", "mobile": "ax"})"));
  ASSERT_TRUE(r.problem);
  EXPECT_EQ(r.problem->constraints[0].fixed.kind, FeatureKind::kLine);
  EXPECT_TRUE(r.problem->constraints[0].fixed.point.isApprox(Vector3d(1, 0, 0)));
}

TEST(SpecParse, DegreesApplyToAnglesAndRpy) {
  std::string s = spec(R"({"type": "angle", "fixed": "K", "mobile": "ax", "value": 90})");
  s.insert(s.find("\"fixed\""), R"("units": {"angle": "deg"}, )");
  s.insert(s.find("\"features\": {\n    \"tcp\""), R"("pose": {"rpy": [0, 0, 90]}, )");
  ParseResult r = parse(s);
  ASSERT_TRUE(r.problem) << r.errors.front().path << r.errors.front().message;
  EXPECT_NEAR(r.problem->constraints[0].value, 1.5707963267948966, 1e-15);
  Vector3d x = r.problem->mobile.pose.linear() * Vector3d::UnitX();
  EXPECT_TRUE(x.isApprox(Vector3d::UnitY(), 1e-12)) << x.transpose();
}

// A plugin-style registry: the built-ins and types registered in-process the way a plugin
// registers them, one of each value kind; the reader knows none of them by name.
const Registry& pluginStyleRegistry() {
  static const Registry* const reg = [] {
    auto* r = new Registry;  // lives as long as the test program
    registerBuiltins(*r);
    const FeaturePair line_line{FeatureKind::kLine, FeatureKind::kLine};
    ConstraintType twist;
    twist.name = "twist";
    twist.description = "an angle-valued plugin type";
    twist.accepts = {line_line};
    twist.value_kind = ValueKind::kAngle;  // takes_value left false: the kind implies it
    twist.origin = "test";
    r->addConstraintType(twist);
    ConstraintType gap = twist;
    gap.name = "gap";
    gap.value_kind = ValueKind::kLength;
    gap.parallel_on = {line_line};
    gap.takes_orientation = false;
    r->addConstraintType(gap);
    r->freeze();
    return r;
  }();
  return *reg;
}

ParseResult parsePluginStyle(std::string constraints, bool degrees) {
  std::string s = spec(constraints);
  if (degrees) s.insert(s.find("\"fixed\""), R"("units": {"angle": "deg"}, )");
  return parseSpec(s, pluginStyleRegistry(), "t");
}

bool warnedAt(const ParseResult& r, const std::string& path, const std::string& needle) {
  for (const auto& w : r.warnings)
    if (w.path == path && w.message.find(needle) != std::string::npos) return true;
  return false;
}

// The unit conversion follows the type's value kind: a plugin's angle-valued type gets deg → rad
// (it used to be read as given, in degrees), a length-valued one is read as given.
TEST(SpecParse, APluginAngleTypeIsReadInTheSpecsAngleUnit) {
  ParseResult r =
      parsePluginStyle(R"({"type": "twist", "fixed": "K", "mobile": "ax", "value": 90})", true);
  ASSERT_TRUE(r.problem) << r.errors.front().path << r.errors.front().message;
  EXPECT_NEAR(r.problem->constraints[0].value, 1.5707963267948966, 1e-15);
  r = parsePluginStyle(R"({"type": "twist", "fixed": "K", "mobile": "ax", "min": 10, "max": 30})",
                       true);
  ASSERT_TRUE(r.problem);
  EXPECT_NEAR(r.problem->constraints[0].min, 10 * kPi / 180, 1e-15);
  EXPECT_NEAR(r.problem->constraints[0].max, 30 * kPi / 180, 1e-15);
  r = parsePluginStyle(R"({"type": "gap", "fixed": "K", "mobile": "ax", "value": 90})", true);
  ASSERT_TRUE(r.problem);
  EXPECT_EQ(r.problem->constraints[0].value, 90.0);
  // A value kind means a value is needed.
  r = parsePluginStyle(R"({"type": "twist", "fixed": "K", "mobile": "ax"})", false);
  EXPECT_FALSE(r.problem);
  ASSERT_FALSE(r.errors.empty());
  EXPECT_EQ(r.errors.front().path, "constraints[0].value");
}

// "parallel" and "orientation" are read where the type says so and warned about elsewhere; the
// warning names where "parallel" does mean something, from the registered types.
TEST(SpecParse, OptionalFieldsFollowTheType) {
  ParseResult r = parsePluginStyle(
      R"({"type": "gap", "fixed": "K", "mobile": "ax", "value": 1, "parallel": true})", false);
  ASSERT_TRUE(r.problem);
  EXPECT_TRUE(r.problem->constraints[0].parallel);
  EXPECT_FALSE(warnedAt(r, "constraints[0].parallel", "")) << r.warnings.size();
  r = parsePluginStyle(
      R"({"type": "twist", "fixed": "K", "mobile": "ax", "value": 1, "parallel": true})", false);
  ASSERT_TRUE(r.problem);
  EXPECT_TRUE(warnedAt(r, "constraints[0].parallel",
                       "only meaningful for a line-line distance or line-line gap (ignored)"));
  r = parsePluginStyle(
      R"({"type": "gap", "fixed": "K", "mobile": "ax", "value": 1, "orientation": "opposed"})",
      false);
  ASSERT_TRUE(r.problem);
  EXPECT_TRUE(warnedAt(r, "constraints[0].orientation", "'gap' takes no orientation"));
  EXPECT_EQ(r.problem->constraints[0].orientation, InputConstraint().orientation);
  // The built-in registry: parallel only on a line-line distance.
  r = parse(spec(R"({"type": "angle", "fixed": "K", "mobile": "ax", "value": 1, "parallel": 1})"));
  EXPECT_FALSE(r.problem);
  r = parse(
      spec(R"({"type": "angle", "fixed": "K", "mobile": "ax", "value": 1, "parallel": false})"));
  ASSERT_TRUE(r.problem);
  EXPECT_TRUE(
      warnedAt(r, "constraints[0].parallel", "only meaningful for a line-line distance (ignored)"));
}

TEST(SpecParse, PoseForms) {
  auto withPose = [](const std::string& pose) {
    std::string s = spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})");
    s.insert(s.find("\"features\": {\n    \"K\""), "\"pose\": " + pose + ", ");
    return s;
  };
  ParseResult q = parse(withPose(R"({"position": [1, 2, 3], "orientation": [0, 0, 2, 2]})"));
  ASSERT_TRUE(q.problem);
  EXPECT_TRUE((q.problem->fixed.pose.linear() * Vector3d::UnitX()).isApprox(Vector3d::UnitY()));
  EXPECT_TRUE(q.problem->fixed.pose.translation().isApprox(Vector3d(1, 2, 3)));
  ParseResult m =
      parse(withPose(R"({"matrix": [[0, -1, 0, 5], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"));
  ASSERT_TRUE(m.problem);
  EXPECT_TRUE(m.problem->fixed.pose.isApprox(q.problem->fixed.pose.linear() *
                                             Isometry3d(Eigen::Translation3d(0, -5, 0))) ||
              m.problem->fixed.pose.translation().isApprox(Vector3d(5, 0, 0)));
  expectError(withPose(R"({"orientation": [0, 0, 0, 0]})"), "fixed.pose.orientation",
              "zero quaternion");
  expectError(withPose(R"({"matrix": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
              "fixed.pose.matrix", "not a rigid transform");
  expectError(withPose(R"({"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1]]})"),
              "fixed.pose.matrix", "not a rigid transform");
  expectError(withPose(R"({"position": [1, "a", 3]})"), "fixed.pose.position[1]",
              "expected a number");
}

TEST(SpecParse, MalformedJsonNamesLineAndColumn) {
  ParseResult r = parse("{\n  \"relpos\": 1,\n  \"fixed\": {,\n}");
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].message.find("malformed JSON at line 3, column"), std::string::npos)
      << r.errors[0].message;
}

TEST(SpecParse, MissingSections) {
  expectError(R"({"relpos": 1, "mobile": {"features": {}}, "constraints": []})", "fixed",
              "missing");
  expectError(R"({"relpos": 1, "fixed": {"features": {}}, "constraints": []})", "mobile",
              "missing");
  expectError(R"({"relpos": 1, "fixed": {"features": {}}, "mobile": {"features": {}}})",
              "constraints", "missing");
}

TEST(SpecParse, UnknownFeatureOrConstraintType) {
  expectError(spec(R"({"type": "welded", "fixed": "K", "mobile": "tcp"})"), "constraints[0].type",
              "unknown constraint type 'welded'");
  expectError(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp2"})"),
              "constraints[0].mobile",
              "no feature 'tcp2' on mobile object 'gripper' (it has: tcp, palm, ax)");
  std::string s = kBase;
  s.replace(s.find("\"point\": [-2"), 8, "\"pint\": ");
  expectError(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})", s.c_str()),
              "fixed.features.Q.pint", "unknown feature kind 'pint'");
}

TEST(SpecParse, FeatureKindTheTypeDoesNotAccept) {
  expectError(spec(R"({"type": "angle", "fixed": "Q", "mobile": "ax", "value": 1})"),
              "constraints[0]", "does not accept point-line");
  expectError(spec(R"({"type": "coincident", "fixed": "K.axis", "mobile": "tcp"})"),
              "constraints[0].fixed", "only a cylinder has an axis");
}

TEST(SpecParse, ZeroDirectionNanAndRadius) {
  std::string s = kBase;
  s.replace(s.find("[0, 2, 0]"), 9, "[0, 0, 0]");
  expectError(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})", s.c_str()),
              "fixed.features.K.line.direction", "zero-length direction");
  std::string r = kBase;
  r.replace(r.find("\"radius\": 0.5"), 13, "\"radius\": -1");
  expectError(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})", r.c_str()),
              "fixed.features.C.cylinder.radius", "positive");
  // JSON has no NaN literal; a number too large for a double is refused at its path, not a crash.
  expectError(spec(R"({"type": "distance", "fixed": "Q", "mobile": "tcp", "value": 1e999})"),
              "constraints[0].value", "number out of the range of a double '1e999'");
}

// Directions, normals and quaternions of any magnitude are normalised without overflow or
// underflow (their squares once overflowed beyond 1e154: directions became zero, quaternions the
// identity); only an exact zero has no direction.
TEST(SpecParse, DirectionsAndQuaternionsOfAnyMagnitude) {
  auto directionOf = [](const std::string& d) {
    std::string s = kBase;
    s.replace(s.find("[0, 2, 0]"), 9, d);
    const ParseResult r =
        parse(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})", s.c_str()));
    EXPECT_TRUE(r.problem) << d << ": " << (r.errors.empty() ? "" : r.errors[0].message);
    return r.problem ? r.problem->fixed.features[0].feature.direction : Vector3d::Zero().eval();
  };
  const Vector3d diagonal = Vector3d(1, 1, 0).normalized();
  for (const char* d : {"[1e200, 1e200, 0]", "[1e-200, 1e-200, 0]", "[1.7e308, 1.7e308, 0]",
                        "[5e-324, 5e-324, 0]", "[3, 3, 0]"}) {
    const Vector3d v = directionOf(d);
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(v[i], diagonal[i]) << d;
  }
  EXPECT_EQ(directionOf("[1e-13, 0, 0]"), Vector3d(1, 0, 0));  // once "zero-length"
  EXPECT_EQ(directionOf("[0, -1e300, 0]"), Vector3d(0, -1, 0));
  const Vector3d third = directionOf("[1e308, -1e308, 1e308]");
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(std::abs(third[i]), 1 / std::sqrt(3.0));

  auto withPose = [](const std::string& pose) {
    std::string s = spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})");
    s.insert(s.find("\"features\": {\n    \"K\""), "\"pose\": " + pose + ", ");
    return s;
  };
  // A quarter turn about z, however the quaternion is scaled: x goes to y.
  for (const char* q : {"[0, 0, 1e200, 1e200]", "[0, 0, 1e-300, 1e-300]", "[0, 0, 2, 2]"}) {
    const ParseResult r = parse(withPose(std::string(R"({"orientation": )") + q + "}"));
    ASSERT_TRUE(r.problem) << q;
    EXPECT_TRUE((r.problem->fixed.pose.linear() * Vector3d::UnitX()).isApprox(Vector3d::UnitY()))
        << q;
  }
  expectError(withPose(R"({"orientation": [0, 0, 0, 0]})"), "fixed.pose.orientation",
              "zero quaternion");
  // A matrix with huge entries is not rigid (and its check does not overflow into a pass).
  expectError(
      withPose(R"({"matrix": [[1e200, 0, 0, 0], [0, 1e200, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
      "fixed.pose.matrix", "not a rigid transform");
  expectError(
      withPose(
          R"({"matrix": [[1e300, 1e300, 0, 0], [-1e300, 1e300, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
      "fixed.pose.matrix", "not a rigid transform");
}

TEST(SpecParse, ValueProblems) {
  expectError(spec(R"({"type": "distance", "fixed": "Q", "mobile": "tcp", "min": 2, "max": 1})"),
              "constraints[0]", "min 2 is greater than max 1");
  expectError(spec(R"({"type": "distance", "fixed": "Q", "mobile": "tcp", "value": -1})"),
              "constraints[0].value", "negative value");
  expectError(spec(R"({"type": "distance", "fixed": "Q", "mobile": "tcp"})"),
              "constraints[0].value", "missing");
  expectError(spec(R"({"type": "angle", "fixed": "K", "mobile": "ax", "value": 4})"),
              "constraints[0].value", "outside [0, pi]");
  expectError(spec(R"({"type": "angle", "fixed": "Pl", "mobile": "ax", "value": 2})"),
              "constraints[0].value", "outside [-pi/2, pi/2]");
  expectError(spec(R"({"type": "parallel", "fixed": "K", "mobile": "ax", "orientation": "up"})"),
              "constraints[0].orientation", "expected");
  // Signed distances may be negative.
  EXPECT_TRUE(
      parse(spec(R"({"type": "distance", "fixed": "Pl", "mobile": "tcp", "value": -1})")).problem);
}

TEST(SpecParse, RangesAndSkewParse) {
  ParseResult r = parse(spec(
      R"({"type": "distance", "fixed": "Q", "mobile": "tcp", "min": 0.02},
         {"type": "distance", "fixed": "K", "mobile": "ax", "value": 1, "parallel": false})"));
  ASSERT_TRUE(r.problem);
  EXPECT_TRUE(r.problem->constraints[0].isRange());
  EXPECT_EQ(r.problem->constraints[0].min, 0.02);
  EXPECT_FALSE(r.problem->constraints[1].parallel);
  Solution s = solve(*r.problem, builtinRegistry());
  // No rule takes a skew line-line distance beside a point's range: the numeric stage's charts
  // answer it (docs/spec.md §8.7), certified, not proven complete.
  EXPECT_EQ(s.status, Status::kSolved) << s.message;
  EXPECT_FALSE(s.complete);
  for (const Branch& b : s.branches) EXPECT_FALSE(b.exact);
}

TEST(SpecParse, ConstraintIdIsEchoed) {
  ParseResult r =
      parse(spec(R"({"type": "coincident", "fixed": "K", "mobile": "nope", "id": "grasp-1"})"));
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].message.find("(constraint id 'grasp-1')"), std::string::npos)
      << r.errors[0].message;
}

TEST(SpecParse, UnknownFieldsAreWarnings) {
  ParseResult r =
      parse(spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp", "colour": "red"})"));
  ASSERT_TRUE(r.problem);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].path, "constraints[0].colour");
}

// Issue 17: what a user most likely meant, after what was wrong.
TEST(SpecParse, MistypedNamesGetADidYouMean) {
  ParseResult f = parse(
      spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp", "orientaton": "either"})"));
  ASSERT_TRUE(f.problem);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_EQ(f.warnings[0].message, "unknown field (ignored); did you mean 'orientation'?");
  expectError(spec(R"({"type": "coincidence", "fixed": "K", "mobile": "tcp"})"),
              "constraints[0].type",
              "unknown constraint type 'coincidence' (did you mean 'coincident'? else load the "
              "plugin that provides it)");
  expectError(spec(R"({"type": "Perpendicular", "fixed": "K", "mobile": "ax"})"),
              "constraints[0].type", "did you mean 'perpendicular'?");
  expectError(spec(R"({"type": "coincident", "fixed": "K", "mobile": "plam"})"),
              "constraints[0].mobile", "(it has: tcp, palm, ax); did you mean 'palm'?");
  // Nothing near: no guess.
  ParseResult far = parse(spec(R"({"type": "welded", "fixed": "K", "mobile": "gripper_tip"})"));
  ASSERT_EQ(far.errors.size(), 2u);
  for (const auto& e : far.errors) EXPECT_EQ(e.message.find("did you mean"), std::string::npos);
}

// Issue 17: a pose with a key it does not know would otherwise be the identity, silently.
TEST(SpecParse, AnUnknownPoseKeyIsAnError) {
  std::string s = spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})");
  s.insert(s.find("\"features\": {\n    \"tcp\""), R"("pose": {"euler": [0, 0, 1]}, )");
  expectError(s, "mobile.pose.euler",
              "unknown pose field (a pose has \"position\", \"orientation\", \"rpy\" or "
              "\"matrix\")");
  std::string typo = spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})");
  typo.insert(typo.find("\"features\": {\n    \"tcp\""),
              R"("pose": {"position": [1, 2, 3], "orientatoin": [0, 0, 0, 1]}, )");
  expectError(typo, "mobile.pose.orientatoin", "did you mean 'orientation'?");
}

TEST(SpecParse, PluginListIsAPathListResolvedAgainstTheSpec) {
  std::string s = spec(R"({"type": "coincident", "fixed": "K", "mobile": "tcp"})");
  s.insert(s.find("\"fixed\""), R"("plugins": ["libsymmetric.so", "/opt/x.so", 3], )");
  ParseResult r = parse(s);
  EXPECT_FALSE(r.problem);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].path, "plugins[2]");
  EXPECT_EQ(r.errors[0].message, "expected a path (string)");
  const std::string file = ::testing::TempDir() + "plugin_list_spec.json";
  std::ofstream(file) << s;
  const auto paths = specPluginPaths(file);
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0], ::testing::TempDir() + "libsymmetric.so");
  EXPECT_EQ(paths[1], "/opt/x.so");
}

TEST(SpecParse, UnknownTypeNamesTheMissingPlugin) {
  ParseResult r = parse(spec(R"({"type": "symmetric", "fixed": "K", "mobile": "tcp"})"));
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].message,
            "unknown constraint type 'symmetric' (load the plugin that provides it)");
}

TEST(SpecParse, EveryProblemIsReportedAtOnce) {
  ParseResult r = parse(spec(R"({"type": "welded", "fixed": "K", "mobile": "tcp"},
                                {"type": "coincident", "fixed": "nope", "mobile": "tcp"})"));
  EXPECT_EQ(r.errors.size(), 2u);
}

}  // namespace
}  // namespace relpos::test
