// Per-object clearance and allowed contacts (docs/spec.md §5.2, issue 17): a part resting on a
// table beside a wall (data/collision/part-on-table-beside-wall.json). With a clearance for
// everything the part can never be free (it touches the table it rests on); the table's own
// clearance 0, or the table as an allowed contact, leaves the clearance to the wall.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>
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

namespace relpos::test {
namespace {

// The part's mesh written in millimetres beside a copy of the spec (meshes by absolute path).
std::string millimetreSpec(const std::filesystem::path& dir, const std::string& extra_mobile) {
  const std::filesystem::path meshes = std::filesystem::path(kSpec).parent_path() / "meshes";
  std::ifstream in(meshes / "part.off");
  std::ofstream out(dir / "part_mm.off");
  std::string magic;
  int nv = 0, nf = 0, ne = 0;
  in >> magic >> nv >> nf >> ne;
  out << magic << "\n" << nv << " " << nf << " " << ne << "\n";
  for (int i = 0; i < 3 * nv; ++i) {
    double x = 0;
    in >> x;
    out << x * 1000 << (i % 3 == 2 ? "\n" : " ");
  }
  out << in.rdbuf();
  out.close();
  std::string text = specText();
  auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("\"meshes/table.off\"", "\"" + (meshes / "table.off").string() + "\"");
  replace("\"meshes/wall.off\"", "\"" + (meshes / "wall.off").string() + "\"");
  replace("\"meshes/part.off\"", "\"part_mm.off\"" + extra_mobile);
  return text;
}

Report scaledReport(const std::string& text, const std::filesystem::path& dir,
                    std::vector<Diagnostic>* warnings) {
  ParseResult r = parseSpec(text, builtinRegistry());
  EXPECT_TRUE(r.problem) << (r.errors.empty() ? "" : r.errors[0].message);
  if (!r.problem) return Report();
  collision::MeshCache cache;
  std::vector<Diagnostic> errors;
  const auto scene = collision::buildScene(*r.problem, dir.string(), cache, &errors, warnings);
  EXPECT_TRUE(scene);
  if (!scene) return Report();
  return evaluate(*r.problem, solve(*r.problem, builtinRegistry()), ReportOptions(), scene.get());
}

TEST(MeshScale, AMeshInOtherUnitsIsToldAndScaled) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("relpos_mesh_scale_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::vector<Diagnostic> unscaled_warnings, scaled_warnings, plain_warnings;
  const Report unscaled = scaledReport(millimetreSpec(dir, ""), dir, &unscaled_warnings);
  ASSERT_EQ(unscaled_warnings.size(), 1u);
  EXPECT_EQ(unscaled_warnings[0].path, "mobile.mesh");
  EXPECT_NE(unscaled_warnings[0].message.find("\"mesh_scale\": 0.001 would make them agree"),
            std::string::npos)
      << unscaled_warnings[0].message;
  // Scaled, it is the part of the original spec: the same verdicts, no warning.
  const Report scaled =
      scaledReport(millimetreSpec(dir, ", \"mesh_scale\": 0.001"), dir, &scaled_warnings);
  EXPECT_TRUE(scaled_warnings.empty());
  const Report plain = filtered(parsed(), 0.0);
  ASSERT_EQ(scaled.collision.size(), plain.collision.size());
  EXPECT_EQ(scaled.collision_free_branches, plain.collision_free_branches);
  for (std::size_t b = 0; b < plain.collision.size(); ++b) {
    EXPECT_EQ(scaled.collision[b].nearest_collides, plain.collision[b].nearest_collides);
    EXPECT_EQ(scaled.collision[b].blocked_samples, plain.collision[b].blocked_samples);
  }
  std::filesystem::remove_all(dir);
  // A scale that is no scale is refused.
  std::string bad = specText();
  bad.insert(bad.find("\"mesh\": \"meshes/part.off\""), R"("mesh_scale": 0, )");
  ParseResult r = parseSpec(bad, builtinRegistry());
  ASSERT_FALSE(r.problem);
  EXPECT_EQ(r.errors[0].path, "mobile.mesh_scale");
}

}  // namespace
}  // namespace relpos::test
