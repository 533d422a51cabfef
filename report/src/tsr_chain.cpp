// A branch as a TSR chain (relpos/report/tsr.hpp): the branch as a product of rigid exponentials,
// X(θ) = Π_k exp(ξ_k (θ_k − θ*_k)) · X(θ*), checked on the branch pose by pose (rigidProduct,
// relpos/report/pose_model.hpp), each factor written as a link (or several as one, when they fit
// one TSR's frame).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "relpos/report/pose_model.hpp"
#include "relpos/report/tsr.hpp"

namespace relpos {
namespace {

// A frame whose z is `z` (unit), at `origin`: x, y completing it deterministically.
Isometry3d frameAlong(const Vector3d& z, const Vector3d& origin) {
  const Vector3d helper = std::abs(z.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d x = (helper - helper.dot(z) * z).normalized();
  Isometry3d F = Isometry3d::Identity();
  F.linear().col(0) = x;
  F.linear().col(1) = z.cross(x);
  F.linear().col(2) = z;
  F.translation() = origin;
  return F;
}

// One link per factor, each a slide on its frame's z or a turn as its yaw: F_k·Xform(b_k)·F_k⁻¹.
// Written as personalrobotics/tsr and or_ompl compose a chain — only the first link's T0_w is
// used, each later link starting at the pose so far — so each frame is folded into the link
// before: T0_w = F_0 on the first link and the identity on the others, Tw_e = F_k⁻¹·F_{k+1}, and
// F_n⁻¹·X(θ*) on the last.
std::vector<TsrLink> linkPerFactor(const std::vector<ScrewFactor>& order, const Isometry3d& X_at) {
  std::vector<TsrLink> chain;
  std::vector<Isometry3d> frames;
  for (const ScrewFactor& f : order) {
    frames.push_back(frameAlong(f.axis, f.turn ? f.point : Vector3d::Zero()));
    TsrLink link;
    link.Bw[f.turn ? 5 : 2] = {f.lo, f.hi};
    chain.push_back(link);
  }
  if (chain.empty()) {
    TsrLink fixed;
    fixed.T0_w = X_at;
    chain.push_back(fixed);
    return chain;
  }
  chain[0].T0_w = frames[0];
  for (std::size_t k = 0; k < chain.size(); ++k)
    chain[k].Tw_e = frames[k].inverse() * (k + 1 < chain.size() ? frames[k + 1] : Isometry3d(X_at));
  return chain;
}

// The whole product as one TSR when it fits one frame: slides along mutually perpendicular
// directions, then at most one turn, about an axis each slide is along or across, as
// T0_w·Trans(x, y, z)·Rz(yaw)·Tw_e applies them (z: the turn's axis).
bool oneLink(const std::vector<ScrewFactor>& order, const Isometry3d& X_at, TsrLink* link) {
  std::vector<const ScrewFactor*> slides;
  const ScrewFactor* turn = nullptr;
  for (const ScrewFactor& f : order) {
    if (turn) return false;  // a slide after the turn, or a second turn
    if (f.turn)
      turn = &f;
    else
      slides.push_back(&f);
  }
  for (std::size_t i = 0; i < slides.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(slides[i]->axis.dot(slides[j]->axis)) > 1e-12) return false;
  // z: the turn's axis, else the first slide; x: the first slide across z.
  Vector3d z = turn ? turn->axis : (slides.empty() ? Vector3d::UnitZ() : slides[0]->axis);
  const ScrewFactor* across = nullptr;
  for (const ScrewFactor* s : slides) {
    const double c = std::abs(s->axis.dot(z));
    if (c > 1e-12 && std::abs(c - 1.0) > 1e-12) return false;  // oblique to the turn
    if (c <= 1e-12 && !across) across = s;
  }
  Isometry3d F = frameAlong(z, turn ? turn->point : Vector3d(X_at.translation()));
  if (across) {
    F.linear().col(0) = across->axis;
    F.linear().col(1) = z.cross(across->axis);
  }
  link->T0_w = F;
  link->Tw_e = F.inverse() * X_at;
  link->Bw = {};
  auto bound = [](double sign, double lo, double hi) {
    return std::array<double, 2>{std::min(sign * lo, sign * hi), std::max(sign * lo, sign * hi)};
  };
  for (const ScrewFactor* s : slides) {
    const Vector3d local = F.linear().transpose() * s->axis;  // ±1 along one of the frame's axes
    int row = 0;
    local.cwiseAbs().maxCoeff(&row);
    link->Bw[static_cast<std::size_t>(row)] = bound(local[row] > 0 ? 1.0 : -1.0, s->lo, s->hi);
  }
  if (turn) link->Bw[5] = bound(1.0, turn->lo, turn->hi);
  return true;
}

}  // namespace

Isometry3d tsrChainPose(const std::vector<TsrLink>& chain,
                        const std::vector<std::array<double, 6>>& b) {
  Isometry3d X = Isometry3d::Identity();
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const std::array<double, 6>& v = b[k];
    Isometry3d xform = Isometry3d::Identity();
    xform.translation() = Vector3d(v[0], v[1], v[2]);
    xform.linear() =
        (Eigen::AngleAxisd(v[5], Vector3d::UnitZ()) * Eigen::AngleAxisd(v[4], Vector3d::UnitY()) *
         Eigen::AngleAxisd(v[3], Vector3d::UnitX()))
            .toRotationMatrix();
    X = X * chain[k].T0_w * xform * chain[k].Tw_e;
  }
  return X;
}

TsrExport tsrChainOf(const Problem& problem, const Branch& branch, const Params& at,
                     double window) {
  TsrExport out;
  if (!branch.exact) {
    out.why = "a numeric branch (a certified chart of a piece of the set), not a closed form";
    return out;
  }
  auto order = rigidProduct(problem, branch, at, window, &out.why, &out.windowed);
  if (!order) return out;
  const Isometry3d X_at = branch.manifold->pose(at);
  TsrLink single;
  out.chain =
      oneLink(*order, X_at, &single) ? std::vector<TsrLink>{single} : linkPerFactor(*order, X_at);
  out.exact = true;
  return out;
}

}  // namespace relpos
