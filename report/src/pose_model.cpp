// A branch's poses for a picture (relpos/report/pose_model.hpp): its screw product when it has
// one, else a table of its poses on a grid through the nearest pose.
#include "relpos/report/pose_model.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "screw_product.hpp"

namespace relpos {

PoseModel poseModelOf(const Problem& problem, const Branch& branch, const Params& at, double window,
                      int table_poses) {
  const Manifold& m = *branch.manifold;
  const int n = m.dof();
  PoseModel model;
  model.at = at;
  model.X_at = m.pose(at);
  for (int i = 0; i < n; ++i)
    detail::boxOf(m.parameter(i), at[i], window, &model.range[i][0], &model.range[i][1]);
  std::string why;
  bool windowed = false;
  // A branch whose code throws beside θ* gets a table (its nodes that throw left out).
  try {
    auto order = screwProduct(problem, branch, at, window, true, &why, &windowed);
    if (!order) {
      const double scale = std::max({1.0, problem.lengthScale(), model.X_at.translation().norm()});
      model.pivot = detail::pivotOf(m, at, model.X_at, scale);
      order = detail::separableProduct(m, at, model.X_at, model.pivot,
                                       detail::checkPoints(m, at, window), scale);
      if (!order) model.pivot = Vector3d::Zero();
    }
    if (order) {
      model.product = true;
      model.factors = std::move(*order);
      return model;
    }
  } catch (const std::exception&) {
  }
  // The grid: about table_poses^(1/n) values per parameter, through θ* so that its pose is a node.
  const int per = std::max(2, static_cast<int>(std::floor(std::pow(static_cast<double>(table_poses),
                                                                   1.0 / std::max(1, n)))));
  std::size_t total = 1;
  for (int i = 0; i < n; ++i) {
    const double lo = model.range[i][0], hi = model.range[i][1];
    const double h = (hi - lo) / (per - 1);
    if (!(h > 0.0)) {  // a parameter pinned by its bounds
      model.range[i] = {at[i], at[i]};
      model.count[i] = 1;
      model.step[i] = 0.0;
      continue;
    }
    const int below = static_cast<int>(std::floor((at[i] - lo) / h + 1e-9));
    const int above = static_cast<int>(std::floor((hi - at[i]) / h + 1e-9));
    // Within the bounds: below·h from θ* may pass them by a rounding.
    model.range[i] = {std::max(lo, at[i] - below * h), std::min(hi, at[i] + above * h)};
    model.count[i] = below + above + 1;
    model.step[i] = h;
    total *= static_cast<std::size_t>(model.count[i]);
  }
  model.table.resize(total, Isometry3d::Identity());
  model.valid.resize(total, false);
  for (std::size_t k = 0; k < total; ++k) {
    Params t = at;
    std::size_t rest = k;
    for (int i = n - 1; i >= 0; --i) {
      const auto c = static_cast<std::size_t>(model.count[i]);
      t[i] = model.range[i][0] + static_cast<double>(rest % c) * model.step[i];
      // θ*'s own node is θ* to the bit, not range + j·step an ulp off it: at a bound where the
      // pose moves as √ of the distance to it (a two-angle branch's limit) an ulp moves it 1e-8.
      if (std::abs(t[i] - at[i]) <= 1e-9 * model.step[i]) t[i] = at[i];
      rest /= c;
    }
    try {
      const Isometry3d X = m.pose(t);
      if (X.matrix().allFinite()) model.table[k] = X, model.valid[k] = true;
    } catch (const std::exception&) {
    }
  }
  return model;
}

std::optional<Isometry3d> modelPose(const PoseModel& model, int dof, const Params& theta) {
  if (model.product)
    return detail::product(model.factors, theta, model.at, model.X_at, model.pivot);
  if (model.table.empty()) return model.X_at;  // no parameters
  std::size_t k = 0;
  for (int i = 0; i < dof; ++i) {
    const int c = model.count[i];
    long j = c > 1 ? std::lround((theta[i] - model.range[i][0]) / model.step[i]) : 0;
    j = std::clamp(j, 0L, static_cast<long>(c - 1));
    k = k * static_cast<std::size_t>(c) + static_cast<std::size_t>(j);
  }
  if (!model.valid[k]) return std::nullopt;
  return model.table[k];
}

}  // namespace relpos
