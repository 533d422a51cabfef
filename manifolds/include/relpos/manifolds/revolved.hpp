#pragma once
// A mixed manifold (Somani 004 Fig. 2c): every pose of a fixed-rotation branch X'(θ), turned
// about one fixed line ℓ (point c, unit direction a):
//   X(φ, θ) = Rot(ℓ, φ) · X'(θ)
// Built when the rotation spins about a and every translational constraint is invariant under
// turning about ℓ (its fixed elements on ℓ, along ℓ, or perpendicular to a): the translation then
// follows the rotation and the two cannot be separated.
#include <string>

#include "relpos/core/manifold.hpp"
#include "relpos/manifolds/separable.hpp"

namespace relpos::manifolds {

class RevolvedManifold final : public MixedManifoldBase<RevolvedManifold> {
 public:
  // `inner` must have a fixed rotation (rotation::Fixed).
  RevolvedManifold(const Vector3d& point, const Vector3d& axis, const SeparableManifold& inner)
      : c_(point), a_(axis), inner_(inner) {}
  static constexpr const char* kTypeName = "Revolved";
  static constexpr const char* kSummary =
      "1 DOF more than a fixed-rotation branch: that branch turned about a fixed line, when "
      "the rotation spins about it and every position constraint is symmetric about it "
      "(Somani 004 Fig. 2c, 2g)";
  const char* typeName() const override { return kTypeName; }
  // What the solver checks a branch of a set turned about a line (ConstraintSet::revolve) is.
  ManifoldKind kind() const override { return ManifoldKind::kRevolved; }
  int dof() const override { return 1 + inner_.dof(); }
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  std::string describe() const override;
  bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) override {
    c_ += offset_W;
    return inner_.rebase(offset_W, offset_M);
  }

 private:
  Isometry3d turn(double phi) const;  // Rot(ℓ, φ)
  Vector3d c_, a_;
  SeparableManifold inner_;
};
// The largest built-in type (core/manifold.hpp: kManifoldStorage leaves room for plugins' too).
static_assert(sizeof(RevolvedManifold) <= kManifoldStorage, "revolved manifold too large");

}  // namespace relpos::manifolds
