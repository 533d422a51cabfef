#pragma once
// A separable solution branch: a rotation part × a translation part that depends on the rotation
// (T = S_f − R S_m, PMF §V).
#include <string>

#include "relpos/core/manifold.hpp"
#include "relpos/manifolds/rotation_part.hpp"
#include "relpos/manifolds/translation_part.hpp"

namespace relpos::manifolds {

class SeparableManifold final : public ManifoldBase<SeparableManifold> {
 public:
  SeparableManifold(const RotationPart& r, const TranslationPart& t) : rot_(r), trans_(t) {}
  const char* typeName() const override { return "separable"; }
  int dof() const override { return rot_.dof() + trans_.dof(); }
  int rotationalDof() const override { return rot_.dof(); }
  int translationalDof() const override { return trans_.dof(); }
  Parameter parameter(int i) const override;
  Isometry3d pose(const Params& theta) const override;
  Params project(const Isometry3d& X) const override;
  // The translation parameters, when its projection is exact.
  unsigned closedFormParams() const override {
    return trans_.projectsExactly() ? ((1u << dof()) - 1u) & ~((1u << rot_.dof()) - 1u) : 0u;
  }
  Isometry3d poseWithTail(const Isometry3d& X, Params* theta) const override;
  std::string describe() const override;
  const RotationPart& rotation() const { return rot_; }
  const TranslationPart& translation() const { return trans_; }

 private:
  RotationPart rot_;
  TranslationPart trans_;
};

}  // namespace relpos::manifolds
