#include "relpos/manifolds/separable.hpp"

namespace relpos::manifolds {

SeparableManifold::SeparableManifold(const RotationPart& r, const TranslationPart& t)
    : rot_(r), trans_(t), dof_(r.dof() + t.dof()) {
  if (!trans_.projectsExactly()) return;
  closed_form_ = ((1u << dof()) - 1u) & ~((1u << rot_.dof()) - 1u);
  const Vector3d* spin_axis = rot_.spinAxis();
  spin_closed_ = spin_axis && trans_.invariantUnderSpin(*spin_axis);
  if (spin_closed_) closed_form_ |= 1u << 1;  // θ: the second rotation parameter of every spin
}

Parameter SeparableManifold::parameter(int i) const {
  const int r = rot_.dof();
  return i < r ? rot_.parameter(i) : trans_.parameter(i - r);
}

Isometry3d SeparableManifold::pose(const Params& theta) const {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = rot_.rotation(theta.data());
  X.translation() = trans_.translation(X.linear(), theta.data() + rot_.dof());
  return X;
}

Params SeparableManifold::project(const Isometry3d& X) const {
  // PMF 003 §V: rotation first (the translation set depends on it), then translation.
  Params theta{};
  rot_.project(X.linear(), theta.data());
  const Matrix3d R = rot_.rotation(theta.data());
  trans_.project(R, X.translation(), theta.data() + rot_.dof());
  return theta;
}

Isometry3d SeparableManifold::poseWithTail(const Isometry3d& X, Params* theta) const {
  Isometry3d Y = Isometry3d::Identity();
  if (spin_closed_) {
    // R = P R(u_m, θ) with P the rotation at θ = 0.
    Params& t = *theta;
    const Matrix3d P = rot_.spinBase(t.data());
    Matrix3d spin;
    t[1] = bestSpinAbout(*rot_.spinAxis(), X.linear().transpose() * P, &spin);
    Y.linear() = P * spin;
  } else {
    Y.linear() = rot_.rotation(theta->data());
  }
  Y.translation() = trans_.projectAndPlace(Y.linear(), X.translation(), theta->data() + rot_.dof());
  return Y;
}

bool SeparableManifold::rebase(const Vector3d& offset_W, const Vector3d& offset_M) {
  TranslationPart moved = trans_;
  moved.translate(offset_W, offset_M);
  *this = SeparableManifold(rot_, moved);
  return true;
}

std::string SeparableManifold::describe() const {
  return std::string("rotation ") + rot_.name() + ", translation " + trans_.name();
}

}  // namespace relpos::manifolds
