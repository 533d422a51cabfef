// Collision tests with FCL (OBBRSS bounding-volume hierarchies, mesh against mesh), with the two
// things FCL's surface test does not give: touching is not colliding, and a closed mesh is a
// solid (an object entirely inside another touches no triangle, so a ray-parity inside test
// catches it).
//
// Touching: a closed mobile mesh is also kept *shrunk*, each vertex moved inward by
// kTouchTolerance along its normal, so every face moves in by at most that much. The shrunk mesh
// misses what the real one only touches (a box resting on a table) and still hits what the real
// one penetrates by more than kTouchTolerance — a yes/no FCL query that stops at the first hit,
// where enumerating every touching triangle pair of two resting 10k-triangle meshes would cost
// milliseconds.
//
// Before any of that, the convex hulls of the meshes' pieces decide most poses exactly and for a
// few dot products (convex_pieces.hpp); FCL sees only what they leave undecided.
#include "relpos/collision/scene.hpp"

#include <fcl/fcl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "convex_pieces.hpp"
#include "solid_inside.hpp"

namespace relpos::collision {
// Measured on 10k-triangle meshes: OBB and kIOS no faster, AABB and RSS far slower, median
// splitting slower than FCL's default (mean).
using BV = fcl::OBBRSSd;
namespace {

std::shared_ptr<fcl::CollisionGeometryd> bvhOf(const std::vector<Vector3d>& vertices,
                                               const std::vector<std::array<int, 3>>& triangles) {
  auto bvh = std::make_shared<fcl::BVHModel<BV>>();
  std::vector<fcl::Triangle> tris;
  tris.reserve(triangles.size());
  for (const auto& t : triangles) tris.emplace_back(t[0], t[1], t[2]);
  bvh->beginModel(static_cast<int>(tris.size()), static_cast<int>(vertices.size()));
  bvh->addSubModel(vertices, tris);
  bvh->endModel();
  bvh->computeLocalAABB();
  return bvh;
}

// The mesh's vertices moved inward by `by` along their (area-weighted) normals; the winding's
// sense is taken from the sign of the enclosed volume, so inward is inward either way.
std::vector<Vector3d> shrunk(const Mesh& m, double by) {
  double volume = 0;
  std::vector<Vector3d> normal(m.vertices.size(), Vector3d::Zero());
  for (const auto& t : m.triangles) {
    const Vector3d &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    volume += a.dot(b.cross(c));
    const Vector3d area = (b - a).cross(c - a);
    for (int k : t) normal[k] += area;
  }
  const double outward = volume >= 0 ? 1.0 : -1.0;
  std::vector<Vector3d> v = m.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (normal[i].norm() > 0) v[i] -= outward * by * normal[i].normalized();
  return v;
}

}  // namespace

class CollisionModel {
 public:
  explicit CollisionModel(const Mesh& m) {
    geometry_ = bvhOf(m.vertices, m.triangles);
    probe_ = m.vertices.front();
    if (m.closed && m.oriented) {
      const std::vector<Vector3d> inner = shrunk(m, kTouchTolerance);
      shrunk_ = bvhOf(inner, m.triangles);
      probe_ = inner.front();
    }
    if (m.closed) inside_ = std::make_unique<detail::SolidInside>(m);
    pieces_ = detail::convexPieces(m);
  }
  const fcl::CollisionGeometryd* geometry() const { return geometry_.get(); }
  // The shrunk solid (nullptr for an open or inconsistently wound mesh).
  const fcl::CollisionGeometryd* shrunkGeometry() const { return shrunk_.get(); }
  // A point of the solid just inside one of its vertices (the vertex itself for an open mesh):
  // inside another solid exactly when this whole solid is, once the surfaces are known apart,
  // and never on a surface it merely touches.
  const Vector3d& probe() const { return probe_; }

  // Whether point p (this mesh's frame) is inside the closed mesh (never for an open one).
  bool inside(const Vector3d& p) const { return inside_ && (*inside_)(p); }
  // The mesh's connected pieces as convex hulls (empty: every verdict goes to FCL).
  const std::vector<detail::ConvexPiece>& pieces() const { return pieces_; }

 private:
  std::shared_ptr<fcl::CollisionGeometryd> geometry_, shrunk_;
  Vector3d probe_;
  std::unique_ptr<detail::SolidInside> inside_;
  std::vector<detail::ConvexPiece> pieces_;
};

ModelPtr buildModel(const Mesh& mesh) { return std::make_shared<const CollisionModel>(mesh); }

ModelPtr MeshCache::get(const std::string& path, std::string* error,
                        std::vector<std::string>* warnings) {
  return get(path, 1.0, error, warnings);
}

ModelPtr MeshCache::get(const std::string& path, double scale, std::string* error,
                        std::vector<std::string>* warnings, double* size) {
  std::lock_guard<std::mutex> lock(mutex_);
  // One entry per file and scale (written exactly, in hex-float).
  char exact[40];
  std::snprintf(exact, sizeof exact, "%a", scale);
  const std::string key = path + '\0' + exact;
  auto it = entries_.find(key);
  if (it == entries_.end()) {
    Entry e;
    Mesh mesh;
    if (readMesh(path, &mesh, &e.error, &e.warnings)) {
      Eigen::AlignedBox3d box;
      for (Vector3d& v : mesh.vertices) box.extend(v *= scale);
      e.size = box.isEmpty() ? 0.0 : box.diagonal().norm();
      e.model = buildModel(mesh);
    }
    it = entries_.emplace(key, std::move(e)).first;
  }
  if (!it->second.model) *error = it->second.error;
  if (warnings)
    warnings->insert(warnings->end(), it->second.warnings.begin(), it->second.warnings.end());
  if (size) *size = it->second.size;
  return it->second.model;
}

namespace {

// The deepest penetration among the first 64 surface contacts FCL reports (0 when the surfaces
// only touch). Bounded: two fine meshes cutting through each other meet in thousands of triangle
// pairs, and enumerating them all costs milliseconds for a number that is only reported.
double deepestContact(const CollisionModel& a, const Isometry3d& Xa, const CollisionModel& b,
                      const Isometry3d& Xb) {
  fcl::CollisionRequestd request(64, true);
  fcl::CollisionResultd result;
  fcl::collide(a.geometry(), Xa, b.geometry(), Xb, request, result);
  double depth = 0.0;
  for (std::size_t i = 0; i < result.numContacts(); ++i)
    depth = std::max(depth, result.getContact(i).penetration_depth);
  return depth;
}

double surfaceDistance(const CollisionModel& a, const Isometry3d& Xa, const CollisionModel& b,
                       const Isometry3d& Xb) {
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  fcl::distance(a.geometry(), Xa, b.geometry(), Xb, request, result);
  return std::max(0.0, result.min_distance);
}

// a's probe point inside the closed mesh b: with the surfaces apart, one point of a inside means
// all of a is.
bool probeInside(const CollisionModel& a, const Isometry3d& Xa, const CollisionModel& b,
                 const Isometry3d& Xb) {
  return b.inside((Xb.inverse() * Xa) * a.probe());
}

// The surfaces meet beyond touching: the shrunk mobile solid against the other mesh (a yes/no
// query); an open mobile mesh has no shrunk solid, so its contacts are measured instead.
bool surfacesMeet(const CollisionModel& m, const Isometry3d& X_WM, const CollisionModel& b,
                  const Isometry3d& X_WO) {
  fcl::CollisionRequestd yes_no;
  fcl::CollisionResultd hit;
  const fcl::CollisionGeometryd* g = m.shrunkGeometry() ? m.shrunkGeometry() : m.geometry();
  fcl::collide(g, X_WM, b.geometry(), X_WO, yes_no, hit);
  if (!hit.isCollision()) return false;
  return m.shrunkGeometry() || deepestContact(m, X_WM, b, X_WO) > kTouchTolerance;
}

}  // namespace

bool Scene::collides(const Isometry3d& X_WM, double call_clearance,
                     std::vector<Contact>* contacts) const {
  bool any = false;
  for (const auto& o : others_) {
    const double clearance = o.clearance >= 0.0 ? o.clearance : call_clearance;
    const CollisionModel& m = *mobile_;
    const CollisionModel& b = *o.model;
    double depth = 0.0;
    bool collides = false;
    const detail::PiecesVerdict hulls =
        detail::piecesVerdict(m.pieces(), X_WM, b.pieces(), o.X_WO, clearance, contacts);
    if (hulls.kind == detail::PiecesVerdict::kFree) continue;
    if (hulls.kind == detail::PiecesVerdict::kCollides) {
      collides = true;  // two convex solids: the depth is exact
      depth = hulls.depth;
    } else if (surfacesMeet(m, X_WM, b, o.X_WO)) {
      collides = true;
      // The depth for the report only: enumerating the contacts is the expensive part.
      if (contacts) depth = std::max(deepestContact(m, X_WM, b, o.X_WO), kTouchTolerance);
    } else if (probeInside(m, X_WM, b, o.X_WO) || probeInside(b, o.X_WO, m, X_WM)) {
      collides = true;  // one solid inside the other: at least this far to get out
      if (contacts) depth = std::max(surfaceDistance(m, X_WM, b, o.X_WO), kTouchTolerance);
    } else if (clearance > 0) {
      const double gap = surfaceDistance(m, X_WM, b, o.X_WO);
      collides = gap < clearance;
      depth = gap - clearance;
    }
    if (!collides) continue;
    any = true;
    if (contacts)
      contacts->push_back({o.name, depth});
    else
      break;
  }
  return any;
}

std::vector<std::string> Scene::checkedAgainst() const {
  std::vector<std::string> names;
  for (const auto& o : others_) names.push_back(o.name);
  return names;
}

namespace {

// A mesh whose size is two orders of magnitude from its object's features' (how far they reach
// from the object's origin) was most likely written in other units: what to say, or "". When
// every feature is at the origin, the problem's size (`problem_size`; 0 for an obstacle, which
// has no features and may be any size) stands in, at 300 times: a 1 cm part in a 1.5 m cell is
// not a units slip, a part in millimetres in metres (about 1000 times) is.
std::string meshSizeMismatch(const ObjectSpec& o, double mesh_size, double problem_size) {
  double reach = 0.0;
  for (const NamedFeature& f : o.features)
    reach = std::max(reach, f.feature.point.norm() + f.feature.radius);
  double limit = 100.0;
  if (!(reach > 0.0)) reach = problem_size, limit = 300.0;
  if (!(reach > 0.0) || !(mesh_size > 0.0)) return "";
  const double ratio = mesh_size / reach;
  if (ratio <= limit && ratio >= 1.0 / limit) return "";
  char text[256];
  std::snprintf(text, sizeof text,
                "the mesh is %.3g across, its object's features reach %.3g (%.0fx %s): is it in "
                "other units? (\"mesh_scale\": %g would make them agree)",
                mesh_size, reach, ratio >= 1 ? ratio : 1 / ratio,
                ratio >= 1 ? "larger" : "smaller",
                std::pow(10.0, std::round(std::log10(reach / mesh_size) / 3) * 3));
  return text;
}

}  // namespace

std::string meshPath(const std::string& spec_dir, const std::string& mesh) {
  return mesh.empty() || mesh[0] == '/' || spec_dir.empty() ? mesh : spec_dir + "/" + mesh;
}

std::unique_ptr<Scene> buildScene(const Problem& problem, const std::string& spec_dir,
                                  MeshCache& cache, std::vector<Diagnostic>* errors,
                                  std::vector<Diagnostic>* warnings) {
  auto load = [&](const ObjectSpec& o, const std::string& json_path,
                  bool an_obstacle = false) -> ModelPtr {
    std::string error;
    std::vector<std::string> notes;
    double size = 0.0;
    ModelPtr m = cache.get(meshPath(spec_dir, o.mesh), o.mesh_scale, &error, &notes, &size);
    if (!m) errors->push_back({json_path, error + " ('" + o.mesh + "')"});
    for (const auto& n : notes) warnings->push_back({json_path, n + " ('" + o.mesh + "')"});
    if (m) {
      const std::string unlike =
          meshSizeMismatch(o, size, an_obstacle ? 0.0 : problem.lengthScale());
      if (!unlike.empty()) warnings->push_back({json_path, unlike + " ('" + o.mesh + "')"});
    }
    return m;
  };
  if (problem.mobile.mesh.empty()) {
    errors->push_back({"mobile.mesh", "collision filtering needs a mesh for the mobile object"});
    return nullptr;
  }
  ModelPtr mobile = load(problem.mobile, "mobile.mesh");
  std::vector<SceneObject> others;
  auto allowed = [&](const std::string& name) {
    return std::find(problem.allowed_contacts.begin(), problem.allowed_contacts.end(), name) !=
           problem.allowed_contacts.end();
  };
  if (!problem.fixed.mesh.empty() && !allowed(problem.fixed.name)) {
    ModelPtr m = load(problem.fixed, "fixed.mesh");
    if (m) others.push_back({problem.fixed.name, problem.fixed.pose, m, problem.fixed.clearance});
  }
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    const ObjectSpec& o = problem.obstacles[i];
    if (allowed(o.name)) continue;
    if (o.mesh.empty()) {
      warnings->push_back(
          {"obstacles[" + std::to_string(i) + "]", "an obstacle without a mesh is not checked"});
      continue;
    }
    ModelPtr m = load(o, "obstacles[" + std::to_string(i) + "].mesh", true);
    if (m) others.push_back({o.name, o.pose, m, o.clearance});
  }
  if (!errors->empty()) return nullptr;
  return std::make_unique<Scene>(std::move(mobile), std::move(others));
}

}  // namespace relpos::collision
