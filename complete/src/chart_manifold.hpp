#pragma once
// A branch of the numeric stage that is a piece of a set of poses (docs/spec.md §8.7): the
// certified chart of chart.hpp, its parameters the tangent coordinates θ over the proven box.
// The chart is shared (immutable) between copies of the branch: a manifold must fit the
// holder's inline storage, and a chart carries its conditions.
#include <memory>

#include "chart.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::complete::detail {

struct ChartData {
  Chart chart;
  Normalisation frame;  // the problem's (pose_conditions.hpp), moved by rebase()
};

class ChartManifold final : public MixedManifoldBase<ChartManifold> {
 public:
  explicit ChartManifold(std::shared_ptr<const ChartData> data) : data_(std::move(data)) {}
  const char* typeName() const override { return "Chart"; }
  int dof() const override { return data_->chart.d; }
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  std::string describe() const override;
  bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) override;
  const ChartData& data() const { return *data_; }

 private:
  std::shared_ptr<const ChartData> data_;
};

}  // namespace relpos::complete::detail
