// relpos view (docs/spec.md §3.12) as a user runs it: the page and its scene, and bad input. What
// the page does in a browser is tests/viewer/browser_test.mjs's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

const std::string kSceneOpen = "<script id=\"relpos-scene\" type=\"application/json\">";

// The scene JSON a page carries.
nlohmann::json sceneOf(const std::string& page) {
  const std::size_t from = page.find(kSceneOpen);
  if (from == std::string::npos) return nullptr;
  const std::size_t start = from + kSceneOpen.size();
  const std::size_t end = page.find("</script>", start);
  return nlohmann::json::parse(page.substr(start, end - start));
}

TEST(CliView, WritesOnePageWithTheSceneAndTheScript) {
  const fs::path d = scratchDir();
  const std::string out = (d / "can.html").string();
  CmdResult r = run("view " RELPOS_DATA_DIR "/scenarios/scenario-d-soda-can-grasp.json -o " + out +
                    " --samples 3 --angles deg");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("wrote " + out + " (2 branches)"), std::string::npos) << r.err;
  const std::string page = slurp(out);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  // Self-contained: no file or address to load.
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("src=\"http"), std::string::npos);
  EXPECT_NE(page.find("Three.js Authors"), std::string::npos);  // the bundled library's licence
  const nlohmann::json scene = sceneOf(page);
  ASSERT_TRUE(scene.is_object());
  EXPECT_EQ(scene["status"], "solved");
  EXPECT_EQ(scene["angles"], "deg");
  ASSERT_EQ(scene["branches"].size(), 2u);
  for (const auto& b : scene["branches"]) {
    EXPECT_EQ(b["samples"].size(), 3u);
    EXPECT_EQ(b["nearest"]["pose"].size(), 16u);
    EXPECT_EQ(b["parameters"].size(), b["dof"].get<std::size_t>());
    EXPECT_TRUE(b["model"]["product"].get<bool>()) << b["manifold"];
    EXPECT_EQ(b["model"]["factors"].size(), b["dof"].get<std::size_t>());
  }
  const nlohmann::json spec =
      nlohmann::json::parse(slurp(RELPOS_DATA_DIR "/scenarios/scenario-d-soda-can-grasp.json"));
  EXPECT_EQ(scene["fixed"]["features"].size(), spec["fixed"]["features"].size());
  EXPECT_EQ(scene["mobile"]["features"].size(), spec["mobile"]["features"].size());
}

TEST(CliView, NamesCannotEndTheScriptAndMeshesComeAlong) {
  const fs::path d = scratchDir();
  // A name that would close the <script> element, and a mesh (the collision example's).
  std::string spec = slurp(RELPOS_DATA_DIR "/collision/part-on-table-beside-wall.json");
  const std::string name_key = "\"name\": \"";
  spec.replace(spec.find(name_key) + name_key.size(), 0, "</script><b>x</b>");
  fs::copy(RELPOS_DATA_DIR "/collision/meshes", d / "meshes", fs::copy_options::recursive);
  const fs::path file = d / "odd-name.json";
  std::ofstream(file) << spec;
  const std::string out = (d / "odd.html").string();
  CmdResult r = run("view " + file.string() + " -o " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = slurp(out);
  EXPECT_EQ(page.find("</script><b>"), std::string::npos);
  const nlohmann::json scene = sceneOf(page);
  ASSERT_TRUE(scene.is_object());
  EXPECT_EQ(scene["name"].get<std::string>().rfind("</script><b>x</b>", 0), 0u);
  EXPECT_GT(scene["mobile"]["mesh"]["positions"].size(), 0u);
  EXPECT_EQ(scene["mobile"]["mesh"]["indices"].size() % 3, 0u);
  EXPECT_GT(scene["obstacles"].size(), 0u);
}

TEST(CliView, BadInputIsOneLineAndExitTwo) {
  const fs::path d = scratchDir();
  std::string spec = slurp(RELPOS_DATA_DIR "/collision/part-on-table-beside-wall.json");
  spec.replace(spec.find("meshes/part.off"), std::string("meshes/part.off").size(), "missing.off");
  const fs::path file = d / "missing-mesh.json";
  std::ofstream(file) << spec;
  const std::string out = (d / "missing.html").string();
  CmdResult r = run("view " + file.string() + " -o " + out);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(file.string() + ": mobile.mesh: mesh file not found"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));  // no partial page
  // The spec itself as the output: refused before anything is written.
  const std::string example = RELPOS_DATA_DIR "/examples/peg-in-hole.json";
  const std::string before = slurp(example);
  CmdResult same = run("view " + example + " -o " + example);
  EXPECT_EQ(same.code, 2);
  EXPECT_EQ(slurp(example), before);
  CmdResult two = run("view " + example + " " + example);
  EXPECT_EQ(two.code, 2);
  EXPECT_NE(two.err.find("view takes exactly one spec file"), std::string::npos) << two.err;
}

}  // namespace
}  // namespace relpos::test
