#include "relpos/manifolds/line_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "chain.hpp"

namespace relpos::manifolds {
using detail::lineFrame;
using detail::rot;
using detail::trans;

LineDistanceManifold::LineDistanceManifold(const Fundamental& f)
    : F_(lineFrame(f.q, f.d)), L_inv_(lineFrame(f.p, f.u).inverse()), lo_(f.lo), hi_(f.hi) {}

Parameter LineDistanceManifold::parameter(int i) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  // Order: psi, t, [v], gamma, s, omega.
  if (ranged() && i == 2) return Parameter{"distance", ParamKind::kLength, lo_, hi_, false};
  if (ranged() && i > 2) --i;
  switch (i) {
    case 0:
      return Parameter{"psi", ParamKind::kAngle, -kPi, kPi, true};
    case 1:
      return Parameter{"t", ParamKind::kLength, -inf, inf, false};
    case 2:
      return Parameter{"gamma", ParamKind::kAngle, -kPi, kPi, true};
    case 3:
      return Parameter{"s", ParamKind::kLength, -inf, inf, false};
    default:
      return Parameter{"omega", ParamKind::kAngle, -kPi, kPi, true};
  }
}

Isometry3d LineDistanceManifold::pose(const Params& th) const {
  const int o = ranged() ? 1 : 0;  // offset of gamma, s, omega
  return F_ * rot(2, th[0]) * trans(2, th[1]) * trans(0, v(th)) * rot(0, th[2 + o]) *
         trans(2, th[3 + o]) * rot(2, th[4 + o]) * L_inv_;
}

Params LineDistanceManifold::project(const Isometry3d& X) const {
  // The mobile line in the fixed line's frame: point a, direction u.
  const Isometry3d Y = F_.inverse() * X * L_inv_.inverse();
  const Vector3d a = Y.translation(), u = Y.linear().col(2);
  // Foot of the common perpendicular on the z axis, and the radial direction to the mobile line.
  Vector3d foot_z, foot_m;
  const bool crossing = closestPointsOfLines(Vector3d::Zero(), Vector3d::UnitZ(), a, u,
                                             kUnitRounding, &foot_z, &foot_m);
  Vector3d radial = foot_m - foot_z;
  radial.z() = 0.0;
  if (radial.norm() < kUnitRounding) {
    // The lines meet (or coincide): any radial direction ⊥ u works; take the one ⊥ u in xy.
    radial = crossing ? Vector3d(Vector3d::UnitZ().cross(u)) : Vector3d::UnitX();
    if (radial.norm() < kUnitRounding) radial = Vector3d::UnitX();
  }
  radial.normalize();
  Params th{};
  const int o = ranged() ? 1 : 0;
  th[0] = std::atan2(radial.y(), radial.x());
  th[1] = foot_z.z();
  const double dist = (foot_m - foot_z).norm();
  if (ranged()) th[2] = std::min(hi_, std::max(lo_, dist));
  // γ: u in the frame after Rz(ψ): Rx(γ) z = (0, −sin γ, cos γ).
  const Matrix3d Rpsi = axisAngle(Vector3d::UnitZ(), th[0]);
  const Vector3d u_local = Rpsi.transpose() * u;
  th[2 + o] = std::atan2(-u_local.y(), u_local.z());
  // s: where the mobile line's own point sits along it from the foot; ω: the remaining spin.
  const Isometry3d base = rot(2, th[0]) * trans(2, th[1]) * trans(0, v(th)) * rot(0, th[2 + o]);
  const Isometry3d rest = base.inverse() * Y;  // ≈ Tz(s) Rz(ω)
  th[3 + o] = rest.translation().z();
  th[4 + o] = std::atan2(rest.linear()(1, 0), rest.linear()(0, 0));
  return th;
}

bool LineDistanceManifold::rebase(const Vector3d& offset_W, const Vector3d& offset_M) {
  F_.pretranslate(offset_W);    // T(offset_W)·F
  L_inv_.translate(-offset_M);  // L⁻¹·T(−offset_M)
  return true;
}

std::string LineDistanceManifold::describe() const {
  return ranged() ? "mixed LineDistance (line at a distance range from a fixed line)"
                  : "mixed LineDistance (line at a fixed distance from a fixed line)";
}

}  // namespace relpos::manifolds
