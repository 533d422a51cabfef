#include "relpos/collision/branch_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "relpos/io/result_writer.hpp"

namespace relpos::collision {
namespace {

// Keeps parameters within their bounds (periodic ones wrapped).
Params clamp(const Manifold& m, Params t) {
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    if (p.periodic)
      t[i] = std::remainder(t[i], 2 * kPi);
    else
      t[i] = std::min(p.max, std::max(p.min, t[i]));
  }
  return t;
}

// The probe step of parameter i at scale s: lengths in units of the window, angles of π.
double step(const Manifold& m, int i, double s, double window) {
  return m.parameter(i).kind == ParamKind::kAngle ? kPi * s : window * s;
}

struct Search {
  const Scene& scene;
  const Manifold& m;
  const Isometry3d& initial;
  double clearance;
  bool free(const Params& t) const { return !scene.collides(m.pose(t), clearance); }
  double distance(const Params& t) const { return poseDistance(m.pose(t), initial); }
};

// From a colliding `blocked` towards a free `open`: the free point nearest the collision
// boundary on the segment, by bisection until the two ends are within 1e-7 (pose distance).
Params boundary(const Search& s, Params blocked, Params open) {
  for (int k = 0; k < 40 && poseDistance(s.m.pose(blocked), s.m.pose(open)) > 1e-7; ++k) {
    Params mid{};
    for (int i = 0; i < s.m.dof(); ++i) mid[i] = 0.5 * (blocked[i] + open[i]);
    (s.free(mid) ? open : blocked) = mid;
  }
  return open;
}

// Compass search over free poses only: a step is taken when it is free and closer. (With one
// parameter the bisection has already found the boundary.)
Params refine(const Search& s, Params t, double window) {
  if (s.m.dof() < 2) return t;
  double d = s.distance(t);
  for (double scale = 1.0 / 16; scale > 1e-5; scale /= 2) {
    bool improved = true;
    for (int round = 0; improved && round < 20; ++round) {
      improved = false;
      for (int i = 0; i < s.m.dof(); ++i)
        for (double sign : {1.0, -1.0}) {
          Params c = t;
          c[i] += sign * step(s.m, i, scale, window);
          c = clamp(s.m, c);
          const double dc = s.distance(c);
          if (dc < d - 1e-12 && s.free(c)) t = c, d = dc, improved = true;
        }
    }
  }
  return t;
}

}  // namespace

BranchCollision filterBranch(const Scene& scene, const Branch& branch, const NearestPose& nearest,
                             const Isometry3d& initial, const FilterOptions& opt) {
  const Manifold& m = *branch.manifold;
  BranchCollision out;
  out.nearest_collides = scene.collides(nearest.pose, opt.clearance, &out.nearest_contacts);
  const Search s{scene, m, initial, opt.clearance};

  // Samples (the single pose of a 0-DOF branch).
  std::mt19937_64 rng(opt.seed);
  const int n = m.dof() == 0 ? 1 : opt.samples;
  Params best{};
  double best_d = std::numeric_limits<double>::infinity();
  auto consider = [&](const Params& t) {
    const double d = s.distance(t);
    if (d < best_d) best = t, best_d = d;
  };
  for (int k = 0; k < n; ++k) {
    const Params t =
        m.dof() == 0 ? Params{} : sampleParameters(m, nearest.parameters, opt.window, rng);
    const Isometry3d X = m.pose(t);
    if (scene.collides(X, opt.clearance)) {
      ++out.blocked_samples;
      continue;
    }
    out.free_samples.push_back({t, X});
    consider(t);
  }

  if (!out.nearest_collides) {
    out.has_nearest_free = true;
    out.nearest_free = nearest;
    return out;
  }
  if (m.dof() == 0) {
    out.nearest_free_reason = "the branch's only pose collides";
    return out;
  }
  // Without a free sample: probes along each parameter around the nearest pose, at growing
  // distances.
  if (!std::isfinite(best_d))
    for (double scale = 1.0 / 64; scale <= 1.0; scale *= 2)
      for (int i = 0; i < m.dof(); ++i)
        for (double sign : {1.0, -1.0}) {
          Params t = nearest.parameters;
          t[i] += sign * step(m, i, scale, opt.window);
          t = clamp(m, t);
          if (s.free(t)) consider(t);
        }
  if (!std::isfinite(best_d)) {
    out.nearest_free_reason = "no collision-free pose among " + std::to_string(n) +
                              " samples and the probes around the nearest pose";
    return out;
  }
  Params t = boundary(s, nearest.parameters, best);
  if (s.distance(t) > best_d) t = best;
  t = refine(s, t, opt.window);
  out.has_nearest_free = true;
  out.nearest_free.parameters = t;
  out.nearest_free.pose = m.pose(t);
  out.nearest_free.distance = s.distance(t);
  return out;
}

nlohmann::ordered_json collisionToJson(const BranchCollision& c, int dof,
                                       const std::vector<std::string>& checked_against,
                                       double clearance) {
  nlohmann::ordered_json j;
  j["checked_against"] = checked_against;
  j["clearance"] = clearance;
  j["nearest_collides"] = c.nearest_collides;
  nlohmann::ordered_json contacts = nlohmann::ordered_json::array();
  for (const auto& k : c.nearest_contacts)
    contacts.push_back({{"object", k.object}, {"depth", k.depth}});
  j["nearest_contacts"] = contacts;
  if (c.has_nearest_free) {
    nlohmann::ordered_json f = poseToJson(c.nearest_free.pose, c.nearest_free.parameters, dof);
    f["distance"] = c.nearest_free.distance;
    j["nearest_free"] = f;
  } else {
    j["nearest_free"] = nullptr;
    j["nearest_free_reason"] = c.nearest_free_reason;
  }
  nlohmann::ordered_json samples = nlohmann::ordered_json::array();
  for (const auto& f : c.free_samples) samples.push_back(poseToJson(f.pose, f.parameters, dof));
  j["free_samples"] = samples;
  j["blocked_samples"] = c.blocked_samples;
  return j;
}

}  // namespace relpos::collision
