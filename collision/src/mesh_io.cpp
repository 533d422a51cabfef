// Mesh reading through CGAL's polygon-soup IO (one reader for STL, OBJ, OFF and PLY), then the
// checks relpos needs before building collision models.
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>

#include "mesh_precheck.hpp"
#include "relpos/collision/mesh.hpp"

namespace relpos::collision {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool supportedExtension(const std::string& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".stl" || ext == ".obj" || ext == ".off" || ext == ".ply";
}

// What would make CGAL's reader misbehave on the file ("" when nothing). OFF and PLY state counts
// that CGAL trusts; STL and OBJ have none (CGAL grows its arrays as it reads, and the indices are
// range-checked below).
std::string precheck(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".off" && ext != ".ply") return "";
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!in || ec) return "";  // CGAL reports it
  std::string text(size, '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return ext == ".off" ? detail::precheckOff(text) : detail::precheckPly(text);
}

}  // namespace

void classify(Mesh& m) {
  std::map<std::pair<int, int>, int> runs;  // directed edge -> how often
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++runs[{t[k], t[(k + 1) % 3]}];
  m.closed = m.oriented = true;
  for (const auto& [edge, n] : runs) {
    const auto back = runs.find({edge.second, edge.first});
    const int reverse = back == runs.end() ? 0 : back->second;
    if (n + reverse != 2) m.closed = false;
    if (n != 1 || reverse != 1) m.oriented = false;
  }
  m.oriented = m.oriented && m.closed;
}

bool readMesh(const std::string& path, Mesh* mesh, std::string* error,
              std::vector<std::string>* warnings) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    *error = "mesh file not found";
    return false;
  }
  if (!supportedExtension(path)) {
    *error = "unsupported mesh format (expected .stl, .obj, .off or .ply)";
    return false;
  }
  std::vector<Kernel::Point_3> points;
  std::vector<std::vector<std::size_t>> faces;
  bool ok = false;
  try {
    if (const std::string problem = precheck(path); !problem.empty()) {
      *error = "unreadable mesh: " + problem;
      return false;
    }
    ok = CGAL::IO::read_polygon_soup(path, points, faces, CGAL::parameters::verbose(false));
  } catch (const std::exception& e) {
    *error = std::string("unreadable mesh: ") + e.what();
    return false;
  }
  if (!ok) {
    *error = "unreadable mesh (not a valid STL, OBJ, OFF or PLY file)";
    return false;
  }
  if (points.empty() || faces.empty()) {
    *error = "empty mesh (no triangles)";
    return false;
  }
  mesh->vertices.clear();
  mesh->triangles.clear();
  for (const auto& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      *error = "mesh has a vertex with a non-finite coordinate";
      return false;
    }
    mesh->vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f].size() != 3) {
      *error = "not a triangle mesh: face " + std::to_string(f) + " has " +
               std::to_string(faces[f].size()) + " vertices";
      return false;
    }
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      if (faces[f][k] >= points.size()) {
        *error = "face " + std::to_string(f) + " refers to a missing vertex";
        return false;
      }
      t[k] = static_cast<int>(faces[f][k]);
    }
    mesh->triangles.push_back(t);
  }
  classify(*mesh);
  if (!mesh->closed && warnings)
    warnings->push_back(
        "open mesh: only its surface is tested (an object entirely inside it is "
        "not seen)");
  else if (!mesh->oriented && warnings)
    warnings->push_back(
        "triangles wound inconsistently: contacts are measured one by one "
        "(slower)");
  return true;
}

bool writeOff(const std::string& path, const Mesh& mesh) {
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << mesh.vertices.size() << " " << mesh.triangles.size() << " 0\n";
  for (const auto& v : mesh.vertices) out << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& t : mesh.triangles) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return static_cast<bool>(out);
}

Mesh boxMesh(const Vector3d& h, int n) {
  Mesh m;
  std::map<std::array<double, 3>, int> index;  // welds the vertices of shared edges
  auto vertex = [&](const Vector3d& p) {
    auto [it, added] =
        index.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(m.vertices.size()));
    if (added) m.vertices.push_back(p);
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<int> grid;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          Vector3d p;
          p[axis] = side * h[axis];
          p[u] = h[u] * (2.0 * i / n - 1);
          p[v] = h[v] * (2.0 * j / n - 1);
          grid.push_back(vertex(p));
        }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int a = grid[i * (n + 1) + j], b = grid[i * (n + 1) + j + 1],
                    c = grid[(i + 1) * (n + 1) + j], d = grid[(i + 1) * (n + 1) + j + 1];
          if (side > 0) {  // outward: (c − a) × (b − a) points along +axis
            m.triangles.push_back({a, c, b});
            m.triangles.push_back({b, c, d});
          } else {
            m.triangles.push_back({a, b, c});
            m.triangles.push_back({b, d, c});
          }
        }
    }
  classify(m);
  return m;
}

Mesh sphereMesh(double r, int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  Mesh m;
  const double ico[12][3] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                             {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                             {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (const auto& v : ico) m.vertices.push_back(r * Vector3d(v[0], v[1], v[2]).normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const std::pair<int, int> key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.vertices.push_back(r * (m.vertices[a] + m.vertices[b]).normalized());
      const int i = static_cast<int>(m.vertices.size()) - 1;
      mid[key] = i;
      return i;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& t : m.triangles) {
      const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
      next.push_back({t[0], a, c});
      next.push_back({t[1], b, a});
      next.push_back({t[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles = std::move(next);
  }
  classify(m);
  return m;
}

}  // namespace relpos::collision
