#include "helical_manifold.hpp"

#include <cmath>
#include <limits>

namespace helical_plugin {
using namespace relpos;

Matrix3d screwBase(const Vector3d& u_m, const Vector3d& d_f) {
  return Quaterniond::FromTwoVectors(u_m, d_f).toRotationMatrix();
}

HelicalManifold::HelicalManifold(const Vector3d& p_m, const Vector3d& u_m, const Vector3d& q_f,
                                 const Vector3d& d_f, double pitch)
    : p_(p_m), q_(q_f), d_(d_f.normalized()), R0_(screwBase(u_m.normalized(), d_)), pitch_(pitch) {}

Parameter HelicalManifold::parameter(int) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return Parameter{"turn", ParamKind::kAngle, -inf, inf, false};
}

Isometry3d HelicalManifold::pose(const Params& theta) const {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = axisAngle(d_, theta[0]) * R0_;
  X.translation() = q_ + pitch_ * theta[0] / (2 * kPi) * d_ - X.linear() * p_;
  return X;
}

Params HelicalManifold::project(const Isometry3d& X) const {
  // The turn about d nearest X's rotation (in (−π, π]), then the whole number of turns whose
  // advance is nearest X's position along the axis.
  const Matrix3d D = X.linear() * R0_.transpose();
  const Vector3d e = anyPerpendicular(d_), f = D * e;
  const double phi = std::atan2(d_.dot(e.cross(f)), e.dot(f));
  const double s = (X * p_ - q_).dot(d_);
  double k = 0.0;
  if (pitch_ != 0.0) k = std::round((s / pitch_) - phi / (2 * kPi));
  Params t{};
  t[0] = phi + 2 * kPi * k;
  return t;
}

std::string HelicalManifold::describe() const {
  return "mixed Helical (pitch " + std::to_string(pitch_) + " per turn)";
}

}  // namespace helical_plugin
