// Reading meshes: the four formats SPEC.md names, and every kind of bad mesh refused with a reason.
#include <gtest/gtest.h>

#include <fstream>

#include "relpos/collision/mesh.hpp"

namespace relpos::test {
namespace {

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// A unit tetrahedron in each format: 4 vertices, 4 triangles, closed.
const char* kOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
const char* kObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
const char* kPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string stl() {
  const double v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string s = "solid tet\n";
  for (const auto& t : f) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (int k : t)
      s += "vertex " + std::to_string(v[k][0]) + " " + std::to_string(v[k][1]) + " " +
           std::to_string(v[k][2]) + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid tet\n";
}

TEST(MeshIo, ReadsOffObjPlyAndStl) {
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"tet.off", kOff}, {"tet.obj", kObj}, {"tet.ply", kPly}, {"tet.stl", stl()}}) {
    collision::Mesh m;
    std::string error;
    std::vector<std::string> warnings;
    ASSERT_TRUE(collision::readMesh(write(name, text), &m, &error, &warnings)) << name << error;
    EXPECT_EQ(m.triangles.size(), 4u) << name;
    EXPECT_TRUE(m.closed) << name;
    EXPECT_TRUE(warnings.empty()) << name;
  }
}

void expectRefused(const std::string& path, const std::string& reason) {
  collision::Mesh m;
  std::string error;
  EXPECT_FALSE(collision::readMesh(path, &m, &error, nullptr)) << path;
  EXPECT_NE(error.find(reason), std::string::npos) << error;
}

TEST(MeshIo, BadMeshesAreRefusedWithTheReason) {
  expectRefused(::testing::TempDir() + "missing.off", "mesh file not found");
  expectRefused(write("garbage.off", "this is not a mesh\n"), "unreadable mesh");
  expectRefused(write("empty.off", "OFF\n0 0 0\n"), "empty mesh");
  expectRefused(write("quads.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
                "not a triangle mesh: face 0 has 4 vertices");
  expectRefused(write("mesh.xyz", kOff), "unsupported mesh format");
}

TEST(MeshIo, AnOpenMeshIsAcceptedWithAWarning) {
  collision::Mesh m;
  std::string error;
  std::vector<std::string> warnings;
  ASSERT_TRUE(collision::readMesh(write("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                                  &m, &error, &warnings));
  EXPECT_FALSE(m.closed);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("open mesh"), std::string::npos);
}

TEST(MeshIo, GeneratedShapesAreClosed) {
  EXPECT_TRUE(collision::boxMesh(Vector3d(1, 2, 3)).closed);
  const collision::Mesh s = collision::sphereMesh(0.5, 2);
  EXPECT_EQ(s.triangles.size(), 320u);
  for (const auto& v : s.vertices) EXPECT_NEAR(v.norm(), 0.5, 1e-12);
}

}  // namespace
}  // namespace relpos::test
