#include "encoding_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace relpos::complete::detail {
namespace {

struct Box {
  Vector3d lo = Vector3d::Constant(std::numeric_limits<double>::infinity());
  Vector3d hi = -lo;
  void add(const Vector3d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  bool empty() const { return !(lo.x() <= hi.x()); }
  Vector3d middle() const { return empty() ? Vector3d::Zero() : Vector3d((lo + hi) / 2.0); }
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
};

}  // namespace

Normalisation normalisationOf(const Problem& problem) {
  Box fixed, mobile;
  double longest = 0.0;
  for (const InputConstraint& c : problem.constraints) {
    fixed.add(c.fixed.placed(problem.fixed.pose).point);
    mobile.add(c.mobile.point);
    if (c.type == "distance" && c.has_value) longest = std::max(longest, std::abs(c.value));
    longest = std::max({longest, c.fixed.radius, c.mobile.radius});
  }
  Normalisation n;
  n.centre_W = fixed.middle();
  n.centre_M = mobile.middle();
  n.scale = std::max({fixed.diagonal(), mobile.diagonal(), longest});
  if (!(n.scale > 0.0) || !std::isfinite(n.scale)) n.scale = 1.0;
  return n;
}

NormalisedConstraint normalised(const Problem& problem, const InputConstraint& c,
                                const Normalisation& n) {
  NormalisedConstraint out;
  out.fixed = c.fixed.placed(problem.fixed.pose);
  out.fixed.point = n.fixedPoint(out.fixed.point);
  out.fixed.radius = n.length(out.fixed.radius);
  out.mobile = c.mobile;
  out.mobile.point = n.mobilePoint(out.mobile.point);
  out.mobile.radius = n.length(out.mobile.radius);
  out.value = c.type == "distance" ? n.length(c.value) : c.value;
  return out;
}

int Slots::shared(Side side, Role role, const Vector3d& v) {
  const auto key =
      std::make_tuple(static_cast<char>(side), static_cast<char>(role), v.x(), v.y(), v.z());
  const auto it = shared_.find(key);
  if (it != shared_.end()) return it->second;
  const int at = unique(v);
  shared_.emplace(key, at);
  return at;
}

int Slots::unique(const Vector3d& v) {
  const int at = size();
  for (int i = 0; i < 3; ++i) params_->push_back(v[i]);
  return at;
}

int Slots::value(double v) {
  params_->push_back(v);
  return size() - 1;
}

void normalsAcross(const Vector3d& u, Vector3d* n1, Vector3d* n2) {
  *n1 = anyPerpendicular(u).normalized();
  *n2 = u.cross(*n1).normalized();
}

std::vector<int> canonicalOrder(const Problem& problem) {
  auto key = [&](int i) {
    const InputConstraint& c = problem.constraints[i];
    const Feature f = c.fixed.placed(problem.fixed.pose);
    const Feature& m = c.mobile;
    return std::make_tuple(c.type, f.kind, m.kind, c.orientation, c.parallel, c.value,
                           std::make_tuple(f.point.x(), f.point.y(), f.point.z(), f.direction.x(),
                                           f.direction.y(), f.direction.z(), f.radius),
                           std::make_tuple(m.point.x(), m.point.y(), m.point.z(), m.direction.x(),
                                           m.direction.y(), m.direction.z(), m.radius));
  };
  std::vector<int> order(problem.constraints.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
  return order;
}

bool angleAt(double v, double at) { return std::abs(v - at) <= kAngleRangeSlack; }

bool isEncodedType(const std::string& type) {
  return type == "distance" || type == "angle" || type == "coincident" || type == "parallel" ||
         type == "perpendicular" || type == "tangent";
}

}  // namespace relpos::complete::detail
