#pragma once
// A separable solution branch: a rotation part × a translation part that depends on the rotation
// (T = S_f − R S_m, PMF §V).
#include <limits>
#include <string>

#include "relpos/core/manifold.hpp"
#include "relpos/manifolds/rotation_part.hpp"
#include "relpos/manifolds/translation_part.hpp"

namespace relpos::manifolds {

class SeparableManifold final : public ManifoldBase<SeparableManifold> {
 public:
  SeparableManifold(const RotationPart& r, const TranslationPart& t);
  const char* typeName() const override { return "separable"; }
  int dof() const override { return dof_; }
  int rotationalDof() const override { return rot_.dof(); }
  int translationalDof() const override { return trans_.dof(); }
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  // The translation parameters, when its projection is exact; and then also the spin θ about
  // the mobile axis u_m of a rotation with a spin (R = … R(u_m, θ): one parallel, one angle, an
  // angle range) when the translation set does not move with it: θ only turns the rotation, and
  // the nearest spin is closed form (on its arc, when it has one). Every parameter, when the
  // translation set does not move with the rotation at all (its mobile points at the mobile
  // origin) and the rotation's projection is its nearest rotation: the projection is then the
  // branch's nearest pose.
  unsigned closedFormParams() const override { return closed_form_; }
  Isometry3d poseWithTail(const Isometry3d& X, Params* theta) const override;
  // With a closed-form spin over a full turn, the angle between u_m's two directions and the
  // translation placed with the rotation at θ = 0 (which the spin does not move): the spin and
  // its matrices are left to poseWithTail.
  double searchDistance(const Isometry3d& X, Params* theta) const override;
  // The rotation part's projection, where it is the nearest rotation in angle.
  double nearestRotation(const Isometry3d& X, Params* theta) const override;
  // The translation part's (TranslationPart::rotationCoupling: |p| for one mobile point p), where
  // its projection is its nearest translation; +inf elsewhere. Decided once, with the closed
  // forms: the search asks it for every nearest pose.
  double rotationCoupling() const override { return coupling_; }
  std::string describe() const override;
  // The translation part's points move; the closed forms are decided again (whether the spin
  // moves the translation depends on where the mobile origin is).
  bool rebase(const Vector3d& offset_W, const Vector3d& offset_M) override;
  const RotationPart& rotation() const { return rot_; }
  const TranslationPart& translation() const { return trans_; }

 private:
  RotationPart rot_;
  TranslationPart trans_;
  int dof_ = 0;  // kept: a translation part of planes counts its rows to know it
  unsigned closed_form_ = 0u;
  int spin_index_ = -1;     // the spin θ (RotationPart::spinAxis) when closed form, else −1
  bool full_spin_ = false;  // a closed-form spin over a full turn (not an arc)
  double coupling_ = std::numeric_limits<double>::infinity();
};
// Stored inline in a Branch (ManifoldHolder): the largest shapes of the two variants together.
static_assert(sizeof(SeparableManifold) <= kManifoldStorage, "separable manifold too large");

}  // namespace relpos::manifolds
