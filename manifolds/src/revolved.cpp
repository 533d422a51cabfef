#include "relpos/manifolds/revolved.hpp"

namespace relpos::manifolds {

Isometry3d RevolvedManifold::turn(double phi) const {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = axisAngle(a_, phi);
  X.translation() = c_ - X.linear() * c_;
  return X;
}

Parameter RevolvedManifold::parameter(int i) const {
  if (i == 0) return Parameter{"phi", ParamKind::kAngle, -kPi, kPi, true};
  return inner_.parameter(i - 1);
}

Isometry3d RevolvedManifold::pose(const Params& theta) const {
  Params rest{};
  for (int i = 1; i < dof(); ++i) rest[i - 1] = theta[i];
  return turn(theta[0]) * inner_.pose(rest);
}

Params RevolvedManifold::project(const Isometry3d& X) const {
  // The turn about a that best maps the inner rotation R0 onto X's rotation (the one-parallelism
  // projection, PMF 003 §V), then the inner branch's own projection of the pose turned back.
  const Matrix3d& R0 = inner_.rotation().as<rotation::Fixed>()->R0;
  rotation::OneParallel spin(R0.transpose() * a_, a_);
  spin.R0 = R0;
  Params theta{};
  spin.project(X.linear(), theta.data());
  const Params rest = inner_.project(turn(-theta[0]) * X);
  for (int i = 1; i < dof(); ++i) theta[i] = rest[i - 1];
  return theta;
}

std::string RevolvedManifold::describe() const {
  return "mixed Revolved about a fixed line (" + inner_.describe() + " turned about it)";
}

}  // namespace relpos::manifolds
