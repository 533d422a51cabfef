#pragma once
// A mixed (non-separable) manifold (Somani 004 §IV-A): every pose at which a mobile line lies at
// a (skew) distance v ∈ [lo, hi] from a fixed line — SPEC's `"parallel": false` line-line
// distance, and cylinder-line tangency (v = r). Written as a chain of elementary motions
// (docs/architecture.md; Ruiz & Ferreira's SE(3) subgroups):
//   X_WM = F · Rz(ψ) · Tz(t) · Tx(v) · Rx(γ) · Tz(s) · Rz(ω) · L⁻¹
// F: frame of the fixed line (z along it), L: frame of the mobile line in the mobile object.
// ψ, t place the foot of the common perpendicular, v its length, γ the mobile line's direction in
// the plane tangent to the cylinder of radius v, s and ω slide and spin the object along its line.
#include <string>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds {

class LineDistanceManifold final : public MixedManifoldBase<LineDistanceManifold> {
 public:
  explicit LineDistanceManifold(const Fundamental& f);
  static constexpr const char* kTypeName = "LineDistance";
  static constexpr const char* kSummary =
      "5 DOF (6 with a range): a mobile line at a skew distance from a fixed line, "
      "as a chain Rz Tz Tx Rx Tz Rz (Somani 004 §IV-A)";
  const char* typeName() const override { return kTypeName; }
  int dof() const override { return ranged() ? 6 : 5; }
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  std::string describe() const override;
  bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) override;

 private:
  bool ranged() const { return lo_ != hi_; }
  // Index of each chain parameter in Params (v is absent when exact).
  double v(const Params& t) const { return ranged() ? t[2] : lo_; }
  Isometry3d F_;      // fixed line frame (world)
  Isometry3d L_inv_;  // inverse of the mobile line frame (mobile object)
  double lo_, hi_;
};

}  // namespace relpos::manifolds
