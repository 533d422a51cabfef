#include "chart_manifold.hpp"

#include <cstdio>

namespace relpos::complete::detail {
namespace {

constexpr const char* kNames[6] = {"chart_1", "chart_2", "chart_3",
                                   "chart_4", "chart_5", "chart_6"};

}  // namespace

Parameter ChartManifold::parameter(int i) const {
  Parameter p;
  p.name = kNames[i];
  // a tangent coordinate mixes turning (the quaternion's vector part) and sliding (lengths over
  // the problem's size): neither an angle nor a length
  p.kind = ParamKind::kOther;
  p.min = -data_->chart.radius[static_cast<std::size_t>(i)];
  p.max = data_->chart.radius[static_cast<std::size_t>(i)];
  p.periodic = false;
  return p;
}

Isometry3d ChartManifold::pose(const Params& theta) const {
  const ChartData& d = *data_;
  std::array<double, 6> th{};
  for (int j = 0; j < d.chart.d; ++j) th[j] = theta[j];
  Matrix3d R;
  Vector3d t;
  chartPose(d.chart, th, &R, &t);
  Isometry3d scaled = Isometry3d::Identity();
  scaled.linear() = R;
  scaled.translation() = t;
  return d.frame.poseOf(scaled);
}

Params ChartManifold::project(const Isometry3d& X) const {
  const ChartData& d = *data_;
  const Isometry3d scaled = d.frame.scaledPose(X);
  const std::array<double, 6> th = chartProject(d.chart, scaled.linear(), scaled.translation());
  Params p{};
  for (int j = 0; j < d.chart.d; ++j) p[j] = th[j];
  return p;
}

std::string ChartManifold::describe() const {
  char s[160];
  std::snprintf(s, sizeof s,
                "Chart: a certified piece of a %d-DOF set of poses (%d equations, %zu "
                "inequalities), slice %.3g",
                data_->chart.d, data_->chart.m, data_->chart.inequalities.size(),
                data_->chart.slice);
  return s;
}

bool ChartManifold::rebase(const Vector3d& offset_W, const Vector3d& offset_M) {
  auto moved = std::make_shared<ChartData>(*data_);
  moved->frame.centre_W += offset_W;
  moved->frame.centre_M += offset_M;
  data_ = std::move(moved);
  return true;
}

}  // namespace relpos::complete::detail
