// Per-object clearance and allowed contacts (docs/spec.md §5.2, issue 17): a part resting on a
// table beside a wall (data/collision/part-on-table-beside-wall.json). With a clearance for
// everything the part can never be free (it touches the table it rests on); the table's own
// clearance 0, or the table as an allowed contact, leaves the clearance to the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "relpos/collision/scene.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

const std::string kSpec = std::string(RELPOS_DATA_DIR) + "/collision/part-on-table-beside-wall.json";

Report filtered(const Problem& p, double clearance) {
  collision::MeshCache cache;
  std::vector<Diagnostic> errors, warnings;
  const auto scene = collision::buildScene(
      p, std::filesystem::path(kSpec).parent_path().string(), cache, &errors, &warnings);
  EXPECT_TRUE(scene) << (errors.empty() ? "" : errors[0].message);
  if (!scene) return Report();
  ReportOptions o;
  o.clearance = clearance;
  return evaluate(p, solve(p, builtinRegistry()), o, scene.get());
}

std::string specText() {
  std::ifstream in(kSpec);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The spec, with `insert_after_first_brace` added as its first member.
Problem parsed(const std::string& insert_after_first_brace = "") {
  std::string text = specText();
  text.insert(text.find('{') + 1, insert_after_first_brace);
  ParseResult r = parseSpec(text, builtinRegistry());
  EXPECT_TRUE(r.problem) << (r.errors.empty() ? "" : r.errors[0].path + ": " + r.errors[0].message);
  return r.problem ? *r.problem : Problem();
}

// Whether the branch's nearest free pose is on the table (which spans x in [-0.6, 0.6]).
bool freeOnTheTable(const CollisionReport& c) {
  return c.has_nearest_free && std::abs(c.nearest_free.pose.translation().x()) <= 0.6;
}

bool touches(const CollisionReport& c, const std::string& object) {
  for (const Contact& k : c.nearest_contacts)
    if (k.object == object) return true;
  return false;
}

TEST(ObjectClearance, TheSupportNeedsNoClearanceToBeTouched) {
  const Problem plain = parsed();
  ASSERT_FALSE(plain.constraints.empty());
  // 1 cm from everything, the table the part rests on too: the nearest pose collides with the
  // table, and the nearest free one is off its edge.
  const Report everything = filtered(plain, 0.01);
  ASSERT_EQ(everything.collision.size(), 1u);
  EXPECT_TRUE(touches(everything.collision[0], "table"));
  EXPECT_FALSE(freeOnTheTable(everything.collision[0]));
  // The table's own clearance 0: 1 cm from the wall only, and a free pose on the table.
  Problem table_zero = plain;
  table_zero.fixed.clearance = 0.0;
  const Report wall_only = filtered(table_zero, 0.01);
  ASSERT_EQ(wall_only.collision.size(), 1u);
  EXPECT_FALSE(touches(wall_only.collision[0], "table"));
  EXPECT_TRUE(freeOnTheTable(wall_only.collision[0]));
}

TEST(ObjectClearance, AnAllowedContactIsLeftOut) {
  const Problem p = parsed(R"("allowed_contacts": ["table"], )");
  ASSERT_EQ(p.allowed_contacts.size(), 1u);
  const Report r = filtered(p, 0.01);
  EXPECT_EQ(r.checked_against, std::vector<std::string>{"wall"});
  ASSERT_EQ(r.collision.size(), 1u);
  EXPECT_TRUE(freeOnTheTable(r.collision[0]));
}

TEST(ObjectClearance, TheSpecSaysItAndRefusesWhatItCannotMean) {
  const std::string text = specText();
  std::string with = text;
  with.insert(with.find("\"mesh\": \"meshes/table.off\""), R"("clearance": 0.002, )");
  ParseResult ok = parseSpec(with, builtinRegistry());
  ASSERT_TRUE(ok.problem);
  EXPECT_EQ(ok.problem->fixed.clearance, 0.002);
  EXPECT_LT(ok.problem->obstacles[0].clearance, 0.0);  // not given: the command's
  std::string negative = text;
  negative.insert(negative.find("\"mesh\": \"meshes/table.off\""), R"("clearance": -1, )");
  ParseResult neg = parseSpec(negative, builtinRegistry());
  ASSERT_FALSE(neg.problem);
  EXPECT_EQ(neg.errors[0].path, "fixed.clearance");
  std::string unknown = text;
  unknown.insert(unknown.find('{') + 1, R"("allowed_contacts": ["tabel"], )");
  ParseResult un = parseSpec(unknown, builtinRegistry());
  ASSERT_FALSE(un.problem);
  EXPECT_EQ(un.errors[0].path, "allowed_contacts[0]");
  EXPECT_NE(un.errors[0].message.find("did you mean 'table'?"), std::string::npos)
      << un.errors[0].message;
}

}  // namespace
}  // namespace relpos::test
