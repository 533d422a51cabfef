#pragma once
// Triangle meshes for collision filtering (docs/spec.md §1 `mesh`): STL, OBJ, OFF or PLY, in the
// object's own frame. Reading uses CGAL's IO; CGAL stays inside collision/src.
#include <array>
#include <string>
#include <vector>

#include "relpos/core/geometry.hpp"

namespace relpos::collision {

struct Mesh {
  std::vector<Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
  // Every edge shared by exactly two triangles: the mesh bounds a solid, so a mesh entirely
  // inside it is detected too (open meshes are surfaces only).
  bool closed = false;
  // Every edge run in opposite directions by its two triangles (one consistent winding). Touching
  // is told from penetrating cheaply only for closed, consistently wound meshes (scene.cpp).
  bool oriented = false;
};

// Sets mesh.closed and mesh.oriented from its triangles.
void classify(Mesh& mesh);

// Reads and checks a mesh: readable, a supported format, non-empty, triangles only, finite
// coordinates, indices in range. On failure returns false with the reason in `error` (without the
// path); an open mesh is accepted with a warning.
bool readMesh(const std::string& path, Mesh* mesh, std::string* error,
              std::vector<std::string>* warnings);

// Writes an OFF file (the bundled example meshes are written by tools/make_meshes).
bool writeOff(const std::string& path, const Mesh& mesh);

// A closed axis-aligned box centred at the origin with half-extents h, wound outward, its faces
// n × n grids of squares (12 n² triangles; n = 29 gives the ~10k-triangle meshes the benchmarks
// use), the vertices of shared edges welded.
Mesh boxMesh(const Vector3d& h, int n = 1);
// A closed sphere of radius r centred at the origin: an icosahedron subdivided `levels` times,
// its vertices on the sphere (an inscribed polyhedron).
Mesh sphereMesh(double r, int levels);

}  // namespace relpos::collision
