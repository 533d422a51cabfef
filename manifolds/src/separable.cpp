#include "relpos/manifolds/separable.hpp"

#include <limits>

namespace relpos::manifolds {

SeparableManifold::SeparableManifold(const RotationPart& r, const TranslationPart& t)
    : rot_(r), trans_(t), dof_(r.dof() + t.dof()) {
  if (!trans_.projectsExactly()) return;
  coupling_ = trans_.rotationCoupling();
  closed_form_ = ((1u << dof()) - 1u) & ~((1u << rot_.dof()) - 1u);
  if (rot_.projectsExactly() && trans_.invariantUnderRotation()) {
    // The distance splits: ‖ΔT‖ depends on the translation parameters alone, the angle on the
    // rotation's alone, and each part's projection is its own nearest.
    closed_form_ = (1u << dof()) - 1u;
    return;
  }
  const Vector3d* spin_axis = rot_.spinAxis();
  if (spin_axis && trans_.invariantUnderSpin(*spin_axis)) {
    spin_index_ = rot_.spinIndex();
    closed_form_ |= 1u << spin_index_;
    const Parameter arc = rot_.parameter(spin_index_);
    full_spin_ = arc.periodic || arc.max - arc.min >= 2 * kPi;
  }
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
  if (closed_form_ == (1u << dof()) - 1u) return pose(*theta = project(X));
  Isometry3d Y = Isometry3d::Identity();
  if (spin_index_ >= 0) {
    // R = P R(u_m, θ) with P the rotation at θ = 0. The angle between R and X's rotation falls
    // as tr(Xᵀ P R(u_m, θ)) = a + r cos(θ − θ*) rises: θ*, or on an arc the end nearer to θ*.
    Params& t = *theta;
    const Matrix3d P = rot_.spinBase(t.data());
    const Vector3d& u = *rot_.spinAxis();
    Matrix3d spin;
    double& s = t[spin_index_];
    s = bestSpinAbout(u, X.linear().transpose() * P, &spin);
    if (!full_spin_) {
      const Parameter arc = rot_.parameter(spin_index_);
      const double on_arc = rotation::ontoArc(s, arc.min, arc.max);
      if (on_arc != s) spin = axisAngle(u, s = on_arc);
    }
    Y.linear() = P * spin;
  } else {
    Y.linear() = rot_.rotation(theta->data());
  }
  Y.translation() = trans_.projectAndPlace(Y.linear(), X.translation(), theta->data() + rot_.dof());
  return Y;
}

double SeparableManifold::searchDistance(const Isometry3d& X, Params* theta) const {
  if (!full_spin_) return poseDistance(poseWithTail(X, theta), X);
  // The rotations P R(u_m, θ) are those taking u_m to P u_m. A rotation by an angle moves no
  // vector farther than that angle, and the least turn taking X u_m onto P u_m is one of them:
  // the least angle from X over the spin is the angle between X u_m and P u_m.
  const Matrix3d P = rot_.spinBase(theta->data());
  const Vector3d& u = *rot_.spinAxis();
  const Vector3d a = P * u, b = X.linear() * u;
  const Vector3d T = trans_.projectAndPlace(P, X.translation(), theta->data() + rot_.dof());
  return (T - X.translation()).norm() + std::atan2(a.cross(b).norm(), a.dot(b));
}

double SeparableManifold::nearestRotation(const Isometry3d& X, Params* theta) const {
  // The rotations of the branch are its rotation part's, whatever the translation.
  if (!rot_.projectsExactly()) return std::numeric_limits<double>::quiet_NaN();
  rot_.project(X.linear(), theta->data());
  return rotationDistance(rot_.rotation(theta->data()), X.linear());
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
