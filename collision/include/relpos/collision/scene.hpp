#pragma once
// The collision scene of one problem: the mobile object's mesh tested against the fixed object's
// and every obstacle's (docs/spec.md §2 "Collision fields"). FCL stays inside collision/src: models
// are opaque here.
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "relpos/collision/mesh.hpp"
#include "relpos/core/diagnostic.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/io/report.hpp"

namespace relpos::collision {

// A mesh turned into FCL's bounding-volume hierarchy, plus what the inside test needs.
class CollisionModel;
using ModelPtr = std::shared_ptr<const CollisionModel>;
ModelPtr buildModel(const Mesh& mesh);

// Models by file path, each read and built once (a batch run shares one cache across its specs
// and threads).
class MeshCache {
 public:
  // The model of the file at `path`, or nullptr with the reason in `error`; warnings (an open
  // mesh) are returned again on every use.
  ModelPtr get(const std::string& path, std::string* error, std::vector<std::string>* warnings);
  // The same with its coordinates multiplied by `scale` (> 0: a mesh in millimetres in a spec in
  // metres takes 0.001), and its size (the diagonal of its bounding box, scaled) in *size.
  ModelPtr get(const std::string& path, double scale, std::string* error,
               std::vector<std::string>* warnings, double* size = nullptr);

 private:
  struct Entry {
    ModelPtr model;
    std::string error;
    std::vector<std::string> warnings;
    double size = 0.0;
  };
  std::mutex mutex_;
  std::map<std::string, Entry> entries_;
};

using Contact = relpos::Contact;  // relpos/io/report.hpp: a result value

struct SceneObject {
  std::string name;
  Isometry3d X_WO;  // its pose in the world
  ModelPtr model;
  double clearance = -1.0;  // ≥ 0: this object's own (ObjectSpec::clearance); else the call's
};

// Penetration up to this depth is touching, not colliding (docs/spec.md §5.2).
inline constexpr double kTouchTolerance = 1e-6;

class Scene {
 public:
  Scene(ModelPtr mobile, std::vector<SceneObject> others)
      : mobile_(std::move(mobile)), others_(std::move(others)) {}
  // Whether the mobile object at X_WM collides with anything: interpenetrates by more than
  // kTouchTolerance, lies inside a closed mesh (or contains one), or comes closer than clearance
  // (an object's own clearance in its place, when it has one).
  // Appends one contact per object it collides with. Thread-safe (const).
  bool collides(const Isometry3d& X_WM, double clearance,
                std::vector<Contact>* contacts = nullptr) const;
  std::vector<std::string> checkedAgainst() const;

 private:
  ModelPtr mobile_;
  std::vector<SceneObject> others_;
};

// The file of an object's `mesh`: as written when absolute (or when there is no spec folder),
// else relative to the spec's folder.
std::string meshPath(const std::string& spec_dir, const std::string& mesh);

// The scene of a problem: mesh paths relative to spec_dir. The mobile object needs a mesh; the
// fixed object and the obstacles without one are left out, and so are the allowed contacts. Errors and warnings carry the JSON
// path ("mobile.mesh", "obstacles[1].mesh").
std::unique_ptr<Scene> buildScene(const Problem& problem, const std::string& spec_dir,
                                  MeshCache& cache, std::vector<Diagnostic>* errors,
                                  std::vector<Diagnostic>* warnings);

}  // namespace relpos::collision
