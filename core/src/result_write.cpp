// The result document (SPEC.md §2).
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>

#include "relpos/core/solver.hpp"
#include "relpos/core/spec_io.hpp"

namespace relpos {
namespace {

// ordered_json: fields come out in the order of SPEC.md §2.
using json = nlohmann::ordered_json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

}  // namespace

json poseToJson(const Isometry3d& X, const Params& theta, int dof) {
  json j;
  json ps = json::array();
  for (int i = 0; i < dof; ++i) ps.push_back(num(theta[i]));
  j["parameters"] = ps;
  const Vector3d t = X.translation();
  j["position"] = {t.x(), t.y(), t.z()};
  Quaterniond q(X.linear());
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();  // one of the two equal quaternions, deterministically
  j["orientation"] = {q.x(), q.y(), q.z(), q.w()};
  return j;
}

json resultToJson(const Problem& problem, const Solution& solution, const ResultOptions& opt) {
  json r;
  r["relpos"] = 1;
  r["name"] = problem.name;
  r["status"] = toString(solution.status);
  // Name the user's constraint ids next to the indices in the message (SPEC: ids are echoed).
  std::string message = solution.message;
  std::string ids;
  for (int k : solution.conflicts) {
    const std::string& id = problem.constraints[static_cast<std::size_t>(k)].id;
    if (!id.empty()) ids += (ids.empty() ? "" : ", ") + std::to_string(k) + " = '" + id + "'";
  }
  if (!ids.empty()) message += " (constraints " + ids + ")";
  r["message"] = message;
  json branches = json::array();
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(opt.seed);
  for (std::size_t b = 0; b < solution.branches.size(); ++b) {
    const Manifold& m = *solution.branches[b].manifold;
    const int dof = m.dof();
    json jb;
    jb["dof"] = dof;
    if (m.rotationalDof() >= 0) {
      jb["rotational_dof"] = m.rotationalDof();
      jb["translational_dof"] = m.translationalDof();
    } else {
      jb["rotational_dof"] = nullptr;
      jb["translational_dof"] = nullptr;
    }
    jb["manifold"] = m.describe();
    json params = json::array();
    for (int i = 0; i < dof; ++i) {
      const Parameter p = m.parameter(i);
      params.push_back({{"name", p.name},
                        {"kind", toString(p.kind)},
                        {"min", num(p.min)},
                        {"max", num(p.max)},
                        {"periodic", p.periodic}});
    }
    jb["parameters"] = params;
    const NearestPose n = nearestOnBranch(solution.branches[b], problem.mobile.pose);
    json jn = poseToJson(n.pose, n.parameters, dof);
    jn["distance"] = n.distance;
    jb["nearest"] = jn;
    if (n.distance < best_d) best_d = n.distance, best = static_cast<int>(b);
    if (opt.samples > 0) {
      json samples = json::array();
      for (int s = 0; s < opt.samples; ++s) {
        const Params t = sampleParameters(m, n.parameters, opt.window, rng);
        samples.push_back(poseToJson(m.pose(t), t, dof));
      }
      jb["samples"] = samples;
    }
    branches.push_back(jb);
  }
  r["branches"] = branches;
  r["best"] = best >= 0 ? json(best) : json(nullptr);
  r["conflicts"] = solution.conflicts;
  r["redundant"] = solution.redundant;
  json rules = json::array();
  for (const char* name : solution.rules) rules.push_back(name);
  r["rules"] = rules;
  r["stats"] = {{"solve_us", solution.solve_us}};
  return r;
}

}  // namespace relpos
