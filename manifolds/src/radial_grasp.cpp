#include "relpos/manifolds/radial_grasp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "chain.hpp"

namespace relpos::manifolds {
using detail::lineFrame;
using detail::rot;

RadialGraspManifold::RadialGraspManifold(const RadialGraspSpec& spec)
    : s_(spec),
      F_(lineFrame(spec.axis_point, spec.axis_dir)),
      L_inv_(lineFrame(spec.tip, spec.approach).inverse()),
      A_(Isometry3d::Identity()) {
  // z onto σx: a quarter turn about y (σ = +1) or its opposite.
  A_.linear() = axisAngle(Vector3d::UnitY(), spec.sigma * kPi / 2);
  // The mobile origin in the approach line's frame: on its z axis, Rz(θ) leaves it in place.
  const Vector3d o = L_inv_.translation();
  spin_closed_ = o.head<2>().norm() <= kUnitRounding * (1.0 + o.norm());
  origin_from_tip_ = A_.linear() * o;
  if (spec.has_height) {
    height_gain_ = spec.axis_dir.dot(spec.plane_normal);
    height_offset_ = (spec.axis_point - spec.plane_point).dot(spec.plane_normal);
  }
}

int RadialGraspManifold::dof() const { return 2 + rRanged() + hFree(); }

// Order: psi, [height], [radius], theta.
Parameter RadialGraspManifold::parameter(int i) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (i == 0) return Parameter{"psi", ParamKind::kAngle, -kPi, kPi, true};
  int k = 1;
  if (hFree() && i == k++)
    return s_.has_height ? Parameter{"height", ParamKind::kLength, s_.h_lo, s_.h_hi, false}
                         : Parameter{"height", ParamKind::kLength, -inf, inf, false};
  if (rRanged() && i == k++)
    return Parameter{"radius", ParamKind::kLength, s_.r_lo, s_.r_hi, false};
  return Parameter{"theta", ParamKind::kAngle, -kPi, kPi, true};
}

double RadialGraspManifold::axisHeightOf(double h) const {
  if (!s_.has_height) return h;
  // (a + z d − q)·n = h along the axis frame's z.
  return (h - height_offset_) / height_gain_;
}

double RadialGraspManifold::planeValueOf(double z) const {
  if (!s_.has_height) return z;
  return z * height_gain_ + height_offset_;
}

Isometry3d RadialGraspManifold::pose(const Params& th) const {
  int k = 1;
  const double h = hFree() ? th[k++] : s_.h_lo;
  const double r = rRanged() ? th[k++] : s_.r_lo;
  // F Rz(ψ) T(r, 0, z) A_σ Rz(θ) L⁻¹, composed as poseWithTail composes it: each Rz turns two
  // columns, and T and A_σ (no translation) need no product of their own. The report's motions
  // take two poses a parameter; the product of six transforms was most of their cost.
  const Matrix3d outer = outerRotation(th[0]);
  const double c = std::cos(th[k]), s = std::sin(th[k]);
  Matrix3d spin;
  spin << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  Isometry3d Y = Isometry3d::Identity();
  Y.linear() = outer * (A_.linear() * (spin * L_inv_.linear()));
  Y.translation() = F_.translation() + outer * (Vector3d(r, 0.0, axisHeightOf(h)) +
                                                A_.linear() * (spin * L_inv_.translation()));
  return Y;
}

Params RadialGraspManifold::project(const Isometry3d& X) const {
  Params th{};
  const Vector3d tip = F_.inverse() * (X * s_.tip);  // fingertip in the axis frame
  th[0] = std::atan2(tip.y(), tip.x());
  int k = 1;
  double h = s_.h_lo;
  if (hFree()) {
    h = planeValueOf(tip.z());
    if (s_.has_height) h = std::min(s_.h_hi, std::max(s_.h_lo, h));
    th[k++] = h;
  }
  double r = s_.r_lo;
  if (rRanged()) {
    r = std::min(s_.r_hi, std::max(s_.r_lo, std::hypot(tip.x(), tip.y())));
    th[k++] = r;
  }
  Isometry3d T = Isometry3d::Identity();
  T.translation() = Vector3d(r, 0.0, axisHeightOf(h));
  const Isometry3d rest = (F_ * rot(2, th[0]) * T * A_).inverse() * X * L_inv_.inverse();
  th[k] = std::atan2(rest.linear()(1, 0), rest.linear()(0, 0));
  return th;
}

unsigned RadialGraspManifold::closedFormParams() const {
  const int lengths = (hFree() ? 1 : 0) + (rRanged() ? 1 : 0);
  const unsigned between = ((1u << lengths) - 1u) << 1;  // the parameters between ψ and θ
  return spin_closed_ ? between | (1u << (lengths + 1)) : between;
}

Matrix3d RadialGraspManifold::outerRotation(double psi) const {
  // Rz(ψ) only turns F's first two columns (the search calls this tens of times a branch).
  const Matrix3d& F = F_.linear();
  const double c = std::cos(psi), s = std::sin(psi);
  Matrix3d outer;
  outer.col(0) = c * F.col(0) + s * F.col(1);
  outer.col(1) = c * F.col(1) - s * F.col(0);
  outer.col(2) = F.col(2);
  return outer;
}

Vector3d RadialGraspManifold::placeTip(const Isometry3d& X, const Matrix3d& outer,
                                       const Vector3d& inner_t, Params* th) const {
  // X = outer · T(r, 0, z) · inner: X's origin in the frame `outer`, less the part that turns
  // with θ, is what (r, 0, z) must match, clamped to the rectangle of radius × height.
  Params& t = *th;
  const Vector3d p = outer.transpose() * (X.translation() - F_.translation()) - inner_t;
  int k = 1;
  double h = s_.h_lo, r = s_.r_lo;
  if (hFree()) {
    h = planeValueOf(p.z());
    if (s_.has_height) h = std::min(s_.h_hi, std::max(s_.h_lo, h));
    t[k++] = h;
  }
  if (rRanged()) t[k] = r = std::min(s_.r_hi, std::max(s_.r_lo, p.x()));
  return F_.translation() + outer * (Vector3d(r, 0.0, axisHeightOf(h)) + inner_t);
}

Isometry3d RadialGraspManifold::poseWithTail(const Isometry3d& X, Params* th) const {
  Params& t = *th;
  const int k_theta = dof() - 1;
  // X = outer · T(r, 0, z) · inner with outer = F Rz(ψ) and inner = A_σ Rz(θ) L⁻¹ (A_σ has no
  // translation).
  const Matrix3d outer = outerRotation(t[0]);
  const Matrix3d P = outer * A_.linear();
  const Matrix3d& Q = L_inv_.linear();
  // R = P Rz(θ) Q: the θ maximising trace(Rz(θ) Q Xᵀ P).
  Matrix3d spin;
  if (spin_closed_)
    t[k_theta] = bestSpinAbout(Vector3d::UnitZ(), Q * X.linear().transpose() * P, &spin);
  else
    spin = axisAngle(Vector3d::UnitZ(), t[k_theta]);
  const Vector3d inner_t = A_.linear() * (spin * L_inv_.translation());
  Isometry3d Y = Isometry3d::Identity();
  Y.linear() = P * (spin * Q);
  Y.translation() = placeTip(X, outer, inner_t, th);
  return Y;
}

double RadialGraspManifold::searchDistance(const Isometry3d& X, Params* th) const {
  if (!spin_closed_) return poseDistance(poseWithTail(X, th), X);
  // R = P Rz(θ) Q takes the approach direction Qᵀz to P z whatever θ; the least angle from X
  // over θ is the angle between X Qᵀz and P z (SeparableManifold::searchDistance says why).
  // The mobile origin lies on the approach line, which Rz(θ) leaves in place.
  const Matrix3d outer = outerRotation((*th)[0]);
  const Vector3d a = outer * A_.linear().col(2);
  const Vector3d b = X.linear() * L_inv_.linear().row(2).transpose();
  const Vector3d T = placeTip(X, outer, origin_from_tip_, th);
  return (T - X.translation()).norm() + std::atan2(a.cross(b).norm(), a.dot(b));
}

double RadialGraspManifold::nearestRotation(const Isometry3d& X, Params* th) const {
  if (!spin_closed_) return std::numeric_limits<double>::quiet_NaN();
  // Over the spin the least angle from X is the angle between a(ψ) = F Rz(ψ) A z and X's approach
  // direction b (searchDistance), and a(ψ) turns p = F A z about the axis f = F z: a·b is
  // p_∥·b + cos ψ p_⊥·b + sin ψ (f × p)·b, greatest at ψ* below (any ψ where b lies along the
  // axis: every ψ is as near).
  const Vector3d f = F_.linear().col(2), p = F_.linear() * A_.linear().col(2);
  const Vector3d b = X.linear() * L_inv_.linear().row(2).transpose();
  const double along = p.dot(b) - p.dot(f) * b.dot(f), across = f.cross(p).dot(b);
  Params& t = *th;
  if (along != 0.0 || across != 0.0) t[0] = std::atan2(across, along);
  const Matrix3d P = outerRotation(t[0]) * A_.linear();
  t[dof() - 1] = bestSpinAbout(Vector3d::UnitZ(), L_inv_.linear() * X.linear().transpose() * P);
  const Vector3d a = P.col(2);
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool RadialGraspManifold::nearestArc(const Isometry3d& X, int* i, double* lo, double* hi) const {
  if (!spin_closed_) return false;
  // The point searched at ψ is F Rz(ψ) w over the rectangle of w = (r, 0, z) + v, v the mobile
  // origin from the fingertip (placeTip): its distance to X's origin x (axis frame) falls as
  // w_x ρx cos(ψ − ψx) rises, nondecreasing in |ψ − ψx| while w_x = r + v_x ≥ 0 over the radii,
  // in |ψ − ψx − π| while w_x ≤ 0 over them (the origin beyond the axis). (w_y = v_y is the
  // origin's offset across the approach line, which a closed-form spin bounds by rounding.)
  const Vector3d& v = origin_from_tip_;
  const bool outside = s_.r_lo + v.x() >= 0.0, beyond = s_.r_hi + v.x() <= 0.0;
  if (!outside && !beyond) return false;
  const Matrix3d& F = F_.linear();
  const Vector3d x = F.transpose() * (X.translation() - F_.translation());
  // The approach directions: F Rz(ψ) c for the branch, b for X (both in the axis frame below);
  // their cosine is c_z b_z + ρc ρb cos(ψ + φc − φb).
  const Vector3d b = F.transpose() * (X.linear() * L_inv_.linear().row(2).transpose());
  const Vector3d c = A_.linear().col(2);
  // Either term (nearly) constant over ψ — X's origin on the axis, its approach along it — leaves
  // the other alone to place the minimum, where rounding decides: the whole turn is searched.
  const double rho_x = std::hypot(x.x(), x.y()), rho_b = std::hypot(b.x(), b.y());
  if (!(rho_x > 1e-9 * (1.0 + x.norm())) || !(rho_b > 1e-9) || !(std::hypot(c.x(), c.y()) > 0.5))
    return false;
  const double psi_x = std::atan2(x.y(), x.x()) + (outside ? 0.0 : kPi);
  const double psi_b = std::atan2(b.y(), b.x()) - std::atan2(c.y(), c.x());
  const double apart = std::remainder(psi_b - psi_x, 2 * kPi);
  // (A margin for the rounding of ψx and ψb, and of w_y's few ulps.)
  constexpr double kMargin = 1e-6;
  *i = 0;
  *lo = std::min(psi_x, psi_x + apart) - kMargin;
  *hi = std::max(psi_x, psi_x + apart) + kMargin;
  return true;
}

bool RadialGraspManifold::rebase(const Vector3d& offset_W, const Vector3d& offset_M) {
  RadialGraspSpec moved = s_;
  moved.axis_point += offset_W;
  moved.plane_point += offset_W;
  moved.tip += offset_M;
  *this = RadialGraspManifold(moved);  // the spin's closed form depends on the mobile origin
  return true;
}

std::string RadialGraspManifold::describe() const {
  return std::string("mixed RadialGrasp (approach ") + (s_.sigma > 0 ? "away from" : "towards") +
         " the axis)";
}

}  // namespace relpos::manifolds
