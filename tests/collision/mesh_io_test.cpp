// Reading meshes: the four formats docs/spec.md §1.7 names, and every kind of bad mesh refused with
// a reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "relpos/collision/mesh.hpp"

namespace relpos::test {
namespace {

// A folder of this process's own: other test runs on the machine write the same names.
std::string scratch() {
  static const std::string dir = [] {
    const std::string d = ::testing::TempDir() + "relpos_mesh_io_" + std::to_string(::getpid());
    std::filesystem::create_directories(d);
    return d + "/";
  }();
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = scratch() + name;
  std::ofstream(path, std::ios::binary) << text;
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
  expectRefused(scratch() + "missing.off", "mesh file not found");
  expectRefused(write("garbage.off", "this is not a mesh\n"), "unreadable mesh");
  expectRefused(write("empty.off", "OFF\n0 0 0\n"), "empty mesh");
  expectRefused(write("quads.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
                "not a triangle mesh: face 0 has 4 vertices");
  expectRefused(write("mesh.xyz", kOff), "unsupported mesh format");
}

// CGAL's OFF and PLY readers trust the counts a file states (allocating what they say) and
// convert a negative OFF index to an unsigned one (undefined behaviour, flagged by UBSan): relpos
// checks them first. Each bad file is refused with its reason, before CGAL reads it.
const char* kTetVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST(MeshIo, OffCountsAndIndicesAreCheckedBeforeCgalReadsThem) {
  const std::string v = kTetVertices;
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"OFF\n4 1 0\n" + v + "3 -1 1 2\n", "OFF face 0 refers to a missing vertex (index -1;"},
      {"OFF\n4 1 0\n" + v + "3 0 1 4\n", "OFF face 0 refers to a missing vertex (index 4;"},
      {"OFF\n4 1 0\n" + v + "3 0 1 1.5\n", "missing vertex (index 1.5;"},
      {"OFF\n2000000000 1 0\n0 0 0\n", "too large: the OFF header counts 2000000000 vertices"},
      {"OFF\n1000 1 0\n" + v, "the OFF header counts 1000 vertices, the file holds 4"},
      {"OFF\n4 100 0\n" + v + "3 0 1 2\n", "the OFF header counts 100 faces, the file holds 1"},
      {"OFF\n4 1 0\n" + v + "1000000000 0 1 2\n", "OFF face 0: its vertex count does not match"},
      {"OFF\n4 1 0\n" + v + "-3 0 1 2\n", "OFF face 0: its vertex count does not match"},
      {"OFF\n4 1 0\n" + v + "junk\n", "OFF face 0 has no vertex count"},
      {"OFF\n4 1 0\n0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n", "OFF vertex 0 has fewer than 3"},
      {"OFF\n4 4 2000000000\n" + v, "bad OFF header"},
      {"OFF\n-4 4 0\n" + v, "bad OFF header"},
      {"NOFF\n4 1 0\n" + v + "3 0 1 2\n", "unsupported OFF variant 'NOFF'"},
      {"OFF BINARY\n", "binary OFF is not supported"},
      {"COFF\n4 1 0\n0 0 0 300 0 0 255\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
       "OFF vertex 0 has a bad colour"},
      {"COFF\n4 1 0\n0 0 0 7\n1 0 0 7\n0 1 0 7\n0 0 1 7\n3 0 1 2\n",
       "OFF vertex 0 has a bad colour"},
      {"COFF\n4 2 0\n" + v + "3 0 1 2 1 0 0\n3 0 1 3\n", "OFF face 1 has a bad colour"}};
  for (const auto& [text, reason] : bad) expectRefused(write("bad.off", text), reason);
  // What the checks must not refuse: comments, blank lines, colours (COFF), colours after a
  // face's indices in plain OFF (CGAL ignores them).
  const std::vector<std::string> good = {
      "# a comment\nOFF\n# counts\n4 4 0\n\n0 0 0 # v0\n1 0 0\n0 1 0\n0 0 1\n"
      "3 0 2 1\n3 0 1 3 255 0 0\n3 0 3 2\n3 1 2 3\n",
      "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 0.5 0.5 0.5 1\n"
      "3 0 2 1 0.2 0.2 0.2\n3 0 1 3 1 1 1\n3 0 3 2 0 0 0 1\n3 1 2 3 9 9 9\n"};
  for (const auto& text : good) {
    collision::Mesh m;
    std::string error;
    EXPECT_TRUE(collision::readMesh(write("good.off", text), &m, &error, nullptr)) << error;
    EXPECT_EQ(m.triangles.size(), 4u) << text;
  }
}

// A binary PLY tetrahedron whose faces are lists with a `length` type of the given size.
template <typename Length>
std::string binaryPly(const std::string& length, bool big_endian, Length first_face_length = 3) {
  std::string s = std::string("ply\nformat ") +
                  (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 4\nproperty list " +
                  length + " int vertex_indices\nend_header\n";
  auto put = [&](auto value) {
    char b[sizeof value];
    std::memcpy(b, &value, sizeof value);
    if (big_endian) std::reverse(b, b + sizeof value);
    s.append(b, sizeof value);
  };
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::int32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& p : v)
    for (float c : p) put(c);
  for (int i = 0; i < 4; ++i) {
    put(i == 0 ? first_face_length : Length{3});
    for (std::int32_t k : f[i]) put(k);
  }
  return s;
}

TEST(MeshIo, PlyListLengthsAndCountsAreCheckedBeforeCgalReadsThem) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nelement face 4\nproperty list ";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {head + "int int vertex_indices\nend_header\n" + kTetVertices + "2000000000 0 2 1\n" +
           "3 0 1 3\n",
       "PLY element 'face' item 0 property 'vertex_indices': a list of 2000000000 values"},
      {head + "int int vertex_indices\nend_header\n" + kTetVertices + "-1 0 2 1\n",
       "a list of -1 values"},
      {head + "uint int vertex_indices\nend_header\n" + kTetVertices + "-1 0 2 1\n",
       "a list of 4294967295 values"},
      {head + "int int vertex_indices\nend_header\n" + kTetVertices + "99999999999 0 2 1\n",
       "property 'vertex_indices': missing or bad value"},
      {binaryPly<std::int32_t>("int", false, 0x7FFFFFFF), "a list of 2147483647 values"},
      {binaryPly<std::int32_t>("int", true, 0x7FFFFFFF), "a list of 2147483647 values"},
      {binaryPly<std::int16_t>("short", false, -2), "a list of -2 values"},
      {"ply\nformat ascii 1.0\nelement vertex 10000000\nend_header\n",
       "PLY element 'vertex' has 10000000 items and no properties"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n",
       "PLY property 'x' before any element"},
      {"ply\nformat ascii 1.0\nelement vertex 4\nproperty int64 x\nend_header\n",
       "unsupported PLY property type 'int64'"},
      {"ply\nformat ascii 1.0\nelement face 1\nproperty list float int "
       "vertex_indices\nend_header\n",
       "unsupported PLY list length type 'float'"},
      {"ply\nformat ascii 1.0\nelement vertex 1000\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n" +
           std::string(kTetVertices),
       "PLY element 'vertex' item 4 property 'x': missing or bad value (the header counts 1000"},
      {"ply\nformat ascii 1.0\nelement vertex 4\n", "PLY header without end_header"}};
  for (const auto& [text, reason] : bad) expectRefused(write("bad.ply", text), reason);
  // Lists with wide length types, and both byte orders, are still read.
  for (const std::string& text :
       {head + "int int vertex_indices\nend_header\n" + kTetVertices +
            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n",
        binaryPly<std::uint8_t>("uchar", false), binaryPly<std::uint8_t>("uint8", true),
        binaryPly<std::uint32_t>("uint", false), binaryPly<std::int16_t>("short", true)}) {
    collision::Mesh m;
    std::string error;
    EXPECT_TRUE(collision::readMesh(write("good.ply", text), &m, &error, nullptr)) << error;
    EXPECT_EQ(m.triangles.size(), 4u);
    EXPECT_TRUE(m.closed);
  }
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
