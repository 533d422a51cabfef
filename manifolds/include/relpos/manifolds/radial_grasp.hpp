#pragma once
// A mixed manifold (Somani 004 §VI-C/D): the radial grasp of a cylinder. The mobile approach line
// meets a fixed axis at a right angle, and a fingertip on the approach line lies at a distance r
// (exact or ranged) from the axis and at a height h (exact, ranged, or free) along it:
//   X_WM = F · Rz(ψ) · T(r, 0, z(h)) · A_σ · Rz(θ) · L⁻¹
// F: the axis frame (z along the axis); A_σ turns the line's z onto ±x (the approach line points
// away from or at the axis: two branches); θ spins the object about its approach line;
// L: the frame of the approach line at the fingertip in the mobile object.
#include <string>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds {

struct RadialGraspSpec {
  Vector3d axis_point, axis_dir;       // fixed axis (world)
  Vector3d tip, approach;              // fingertip and approach direction (mobile frame)
  double r_lo = 0.0, r_hi = 0.0;       // distance of the tip from the axis
  bool has_height = false;             // a point-plane constraint on the tip
  Vector3d plane_point, plane_normal;  // its plane (world), normal along the axis
  double h_lo = 0.0, h_hi = 0.0;       // its signed value
  double sigma = 1.0;                  // approach direction: +1 away from the axis, -1 towards
};

class RadialGraspManifold final : public MixedManifoldBase<RadialGraspManifold> {
 public:
  explicit RadialGraspManifold(const RadialGraspSpec& spec);
  static constexpr const char* kTypeName = "RadialGrasp";
  static constexpr const char* kSummary =
      "2-4 DOF: an approach line meeting a fixed axis at a right angle, the "
      "fingertip on it at a distance (range) and height (range) (Somani 004 §VI)";
  const char* typeName() const override { return kTypeName; }
  int dof() const override;
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  // Height and radius: for fixed ψ and θ the rotation is fixed and the fingertip moves on a
  // rectangle (radius × height) in the plane through the axis, so clamping is the nearest point.
  // And θ when the mobile origin lies on the approach line: the spin then moves only the
  // rotation, and the nearest spin is closed form.
  unsigned closedFormParams() const override;
  Isometry3d poseWithTail(const Isometry3d& X, Params* theta) const override;
  // With the spin closed form, the angle between the approach line's two directions (the least
  // angle over the spin) and the fingertip placed without the spin, which does not move it.
  double searchDistance(const Isometry3d& X, Params* theta) const override;
  // With the spin closed form: ψ turns the approach direction about the axis, and the nearest
  // rotation is where it comes nearest X's approach direction (a turn's closed form).
  double nearestRotation(const Isometry3d& X, Params* theta) const override;
  // With the spin closed form, the distance searched at ψ is f(|ψ − ψx|) + g(|ψ − ψb|) in
  // circular distances, both nondecreasing: the fingertip's distance to X's over the radius ×
  // height rectangle turned to ψ (ψx: X's origin's azimuth about the axis), and the angle
  // between the approach directions (ψb: where they come nearest). Any ψ is then no nearer than
  // the point of the shorter arc from ψx to ψb as far from ψx (the circle's triangle inequality):
  // the nearest ψ lies on that arc.
  bool nearestArc(const Isometry3d& X, int* i, double* lo, double* hi) const override;
  std::string describe() const override;
  bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) override;

 private:
  bool rRanged() const { return s_.r_lo != s_.r_hi; }
  // The height is a parameter when ranged or unconstrained.
  bool hFree() const { return !s_.has_height || s_.h_lo != s_.h_hi; }
  double axisHeightOf(double h) const;  // z along the axis for a plane value h
  double planeValueOf(double z) const;
  // F Rz(ψ): the axis frame's rotation turned by ψ.
  Matrix3d outerRotation(double psi) const;
  // The height and radius nearest X (set in θ) for the frame `outer` and the part of the origin
  // that turns with θ, `inner_t`; returns the pose's translation.
  Vector3d placeTip(const Isometry3d& X, const Matrix3d& outer, const Vector3d& inner_t,
                    Params* theta) const;
  RadialGraspSpec s_;
  Isometry3d F_, L_inv_, A_;
  bool spin_closed_ = false;
  // What every pose the search weighs would recompute: the mobile origin from the fingertip in
  // the frame after A_σ (A_σ L⁻¹'s translation, on the approach line when the spin is closed
  // form), and the height's plane value as gain · z + offset.
  Vector3d origin_from_tip_ = Vector3d::Zero();
  double height_gain_ = 1.0, height_offset_ = 0.0;
};

}  // namespace relpos::manifolds
