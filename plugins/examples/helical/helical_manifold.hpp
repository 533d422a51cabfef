#pragma once
// A screw motion about a fixed axis (point q, unit direction d): one parameter, the turn θ
// (unbounded: a thread can turn many times), advancing `pitch` along the axis per full turn.
//   R(θ) = Rot(d, θ) R0,   R(θ) p + T(θ) = q + (pitch θ / 2π) d
// R0 is the shortest rotation taking the mobile line's direction u onto d, p the mobile line's
// point: at θ = 0 the mobile line's point sits on q.
#include "relpos/core/manifold.hpp"

namespace helical_plugin {

class HelicalManifold final : public relpos::MixedManifoldBase<HelicalManifold> {
 public:
  HelicalManifold(const relpos::Vector3d& p_m, const relpos::Vector3d& u_m,
                  const relpos::Vector3d& q_f, const relpos::Vector3d& d_f, double pitch);
  const char* typeName() const override { return "Helical"; }
  int dof() const override { return 1; }
  relpos::Parameter parameter(int i) const override;
  relpos::Isometry3d pose(const relpos::Params& theta) const override;
  relpos::Params project(const relpos::Isometry3d& X) const override;
  std::string describe() const override;

 private:
  relpos::Vector3d p_, q_, d_;
  relpos::Matrix3d R0_;
  double pitch_;
};

// R0: the shortest rotation taking u onto d (Eigen's FromTwoVectors).
relpos::Matrix3d screwBase(const relpos::Vector3d& u_m, const relpos::Vector3d& d_f);

}  // namespace helical_plugin
