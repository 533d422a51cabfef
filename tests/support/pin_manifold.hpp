#pragma once
// A test manifold whose nearest pose can be proven wrongly (Manifold::rotationCoupling): the
// mobile object turns about z through its point (5, 0, 0), held at the world's (1, 0, 0) — poses
// of a point-on-point coincidence — so its positions move 5 a radian with the turn, while it
// claims the coupling it is given. Claiming 1, the nearest pose of an initial pose with one of its
// rotations keeps that rotation, said proven, where a turn is nearer; claiming 5, nothing.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "relpos/core/manifold.hpp"

namespace relpos::test {

class PinManifold final : public MixedManifoldBase<PinManifold> {
 public:
  explicit PinManifold(double claimed) : claimed_(claimed) {}
  const char* typeName() const override { return "Pin"; }
  int dof() const override { return 1; }
  Parameter parameter(int) const override { return {"turn", ParamKind::kAngle, -0.5, 0.5, false}; }
  Isometry3d pose(const Params& t) const override {
    Isometry3d X = Isometry3d::Identity();
    X.linear() = Eigen::AngleAxisd(t[0], Vector3d::UnitZ()).toRotationMatrix();
    X.translation() = Vector3d(1, 0, 0) - X.linear() * Vector3d(5, 0, 0);
    return X;
  }
  Params project(const Isometry3d& X) const override {
    return Params{std::clamp(std::atan2(X.linear()(1, 0), X.linear()(0, 0)), -0.5, 0.5)};
  }
  double nearestRotation(const Isometry3d& X, Params* t) const override {
    (*t)[0] = project(X)[0];
    return rotationDistance(pose(*t).linear(), X.linear());
  }
  double rotationCoupling() const override { return claimed_; }
  std::string describe() const override { return "pin"; }

 private:
  double claimed_;
};

}  // namespace relpos::test
