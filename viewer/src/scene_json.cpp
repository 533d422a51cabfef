// The scene of a page (scene_json.hpp): objects with their features and meshes, and per branch
// its nearest pose, samples, parameters with their motions, and a model of its poses the page's
// script evaluates (relpos/report/pose_model.hpp).
#include "scene_json.hpp"

#include <algorithm>
#include <exception>

#include "relpos/collision/mesh.hpp"
#include "relpos/collision/scene.hpp"
#include "relpos/report/pose_model.hpp"

namespace relpos::viewer::detail {
namespace {

using nlohmann::json;

json vec(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Column-major, as three.js's Matrix4.fromArray reads it.
json matrix(const Isometry3d& X) {
  json a = json::array();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a.push_back(X.matrix()(r, c));
  return a;
}

json featureJson(const NamedFeature& nf) {
  const Feature& f = nf.feature;
  json j = {{"name", nf.name},
            {"kind", toString(f.kind)},
            {"point", vec(f.point)},
            {"direction", vec(f.direction)}};
  if (f.kind == FeatureKind::kCylinder) j["radius"] = f.radius;
  return j;
}

// An object's mesh, read and scaled; *extent grows to its farthest vertex from the object's
// origin. False with the problem in *errors.
bool meshJson(const ObjectSpec& o, const std::string& json_path, const std::string& spec_dir,
              json* out, double* extent, std::vector<Diagnostic>* errors,
              std::vector<Diagnostic>* warnings) {
  *out = nullptr;
  if (o.mesh.empty()) return true;
  const std::string path = collision::meshPath(spec_dir, o.mesh);
  collision::Mesh mesh;
  std::string error;
  std::vector<std::string> notes;
  if (!collision::readMesh(path, &mesh, &error, &notes)) {
    errors->push_back({json_path, error + " ('" + o.mesh + "')"});
    return false;
  }
  for (const auto& n : notes) warnings->push_back({json_path, n + " ('" + o.mesh + "')"});
  // Single precision: what the graphics card draws in, and half the page's size.
  std::vector<float> positions;
  positions.reserve(3 * mesh.vertices.size());
  for (const Vector3d& v : mesh.vertices) {
    const Vector3d s = o.mesh_scale * v;
    *extent = std::max(*extent, s.norm());
    for (int k = 0; k < 3; ++k) positions.push_back(static_cast<float>(s[k]));
  }
  std::vector<int> indices;
  indices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  *out = {{"positions", positions}, {"indices", indices}};
  return true;
}

bool objectJson(const ObjectSpec& o, const std::string& json_path, const std::string& spec_dir,
                json* out, double* extent, std::vector<Diagnostic>* errors,
                std::vector<Diagnostic>* warnings) {
  json features = json::array();
  for (const NamedFeature& f : o.features) features.push_back(featureJson(f));
  json mesh;
  const bool ok = meshJson(o, json_path + ".mesh", spec_dir, &mesh, extent, errors, warnings);
  *out = {{"name", o.name}, {"pose", matrix(o.pose)}, {"features", features}, {"mesh", mesh}};
  return ok;
}

json motionJson(const ParameterMotion& m) {
  json j = {{"type", toString(m.type)}};
  if (m.type == ParameterMotion::Type::kNone || m.type == ParameterMotion::Type::kUnknown) return j;
  j["axis"] = vec(m.axis);
  if (m.type != ParameterMotion::Type::kTranslation) j["point"] = vec(m.point);
  if (m.type == ParameterMotion::Type::kScrew) j["pitch"] = m.pitch;
  return j;
}

json modelJson(const PoseModel& m, int dof) {
  json at = json::array(), range = json::array(), count = json::array(), step = json::array();
  for (int i = 0; i < dof; ++i) {
    at.push_back(m.at[i]);
    range.push_back({m.range[i][0], m.range[i][1]});
    count.push_back(m.count[i]);
    step.push_back(m.step[i]);
  }
  json j = {{"product", m.product}, {"at", at}, {"X_at", matrix(m.X_at)}, {"range", range}};
  if (m.product) {
    json factors = json::array();
    for (const ScrewFactor& f : m.factors)
      factors.push_back({{"param", f.param},
                         {"turn", f.turn},
                         {"orients", f.orients},
                         {"moves", f.moves},
                         {"axis", vec(f.axis)},
                         {"point", vec(f.point)},
                         {"pitch", f.pitch},
                         {"rate", f.rate}});
    j["factors"] = factors;
    j["pivot"] = vec(m.pivot);
    return j;
  }
  json table = json::array();
  for (std::size_t k = 0; k < m.table.size(); ++k)
    table.push_back(m.valid[k] ? matrix(m.table[k]) : json(nullptr));
  j["count"] = count;
  j["step"] = step;
  j["table"] = table;
  return j;
}

json branchJson(const Problem& problem, const Branch& branch, const Report& report, std::size_t i,
                const ViewOptions& options) {
  const BranchReport& br = report.branches[i];
  const int dof = br.dof;
  json params = json::array(), theta = json::array();
  for (int k = 0; k < dof; ++k) {
    const Parameter& p = br.parameters[static_cast<std::size_t>(k)];
    const ParameterMotion& mo = br.motions[static_cast<std::size_t>(k)];
    json pj = {{"name", p.name},
               {"kind", toString(p.kind)},
               {"periodic", p.periodic},
               {"motion", motionJson(mo)},
               {"constraint", mo.constraint}};
    if (!mo.constraint_id.empty()) pj["constraint_id"] = mo.constraint_id;
    params.push_back(pj);
    theta.push_back(br.nearest.parameters[static_cast<std::size_t>(k)]);
  }
  PoseModel model;
  try {
    model =
        poseModelOf(problem, branch, br.nearest.parameters, options.window, options.table_poses);
  } catch (const std::exception&) {  // a plugin's pose function that throws at the nearest pose
    model = PoseModel();
    model.at = br.nearest.parameters;
    model.X_at = br.nearest.pose;
    for (int k = 0; k < dof; ++k) model.range[k] = {model.at[k], model.at[k]}, model.count[k] = 1;
    model.table = {br.nearest.pose};
    model.valid = {true};
  }
  json samples = json::array();
  for (std::size_t s = 0; s < br.sample_count; ++s)
    samples.push_back(matrix(report.samplesOf(i)[s].pose));
  json j = {{"index", i},
            {"manifold", br.manifold},
            {"dof", dof},
            {"exact", br.exact},
            {"nearest",
             {{"parameters", theta},
              {"pose", matrix(br.nearest.pose)},
              {"distance", br.nearest.distance}}},
            {"parameters", params},
            {"model", modelJson(model, dof)},
            {"samples", samples}};
  if (report.collision_checked && i < report.collision.size()) {
    const CollisionReport& c = report.collision[i];
    json contacts = json::array();
    for (const Contact& k : c.nearest_contacts)
      contacts.push_back({{"object", k.object}, {"depth", k.depth}});
    j["collision"] = {
        {"nearest_collides", c.nearest_collides},
        {"contacts", contacts},
        {"nearest_free", c.has_nearest_free ? matrix(c.nearest_free.pose) : json(nullptr)}};
  }
  return j;
}

}  // namespace

bool sceneJson(const Problem& problem, const Solution& solution, const Report& report,
               const ViewOptions& options, json* scene, std::vector<Diagnostic>* errors,
               std::vector<Diagnostic>* warnings) {
  double extent = problem.lengthScale();
  json fixed, mobile;
  bool ok = objectJson(problem.fixed, "fixed", options.spec_dir, &fixed, &extent, errors, warnings);
  ok = objectJson(problem.mobile, "mobile", options.spec_dir, &mobile, &extent, errors, warnings) &&
       ok;
  json obstacles = json::array();
  for (std::size_t i = 0; i < problem.obstacles.size(); ++i) {
    json o;
    // An obstacle's own extent would size the features to a room: it is left out.
    double unused = 0.0;
    ok = objectJson(problem.obstacles[i], "obstacles[" + std::to_string(i) + "]", options.spec_dir,
                    &o, &unused, errors, warnings) &&
         ok;
    obstacles.push_back(o);
  }
  if (!ok) return false;
  json branches = json::array();
  for (std::size_t i = 0; i < report.branches.size() && i < solution.branches.size(); ++i)
    branches.push_back(branchJson(problem, solution.branches[i], report, i, options));
  *scene = {{"relpos", 1},
            {"name", problem.name},
            {"status", toString(report.status)},
            {"complete", report.complete},
            {"message", report.message},
            {"size", extent > 0.0 ? extent : 1.0},
            {"angles", options.degrees ? "deg" : "rad"},
            {"best", report.best},
            {"fixed", fixed},
            {"mobile", mobile},
            {"obstacles", obstacles},
            {"branches", branches}};
  return true;
}

}  // namespace relpos::viewer::detail
