// A branch as a TSR chain (relpos/report/tsr.hpp): find an order of its parameters in which the
// branch is a product of exponentials, X(θ) = Π_k exp(ξ_k (θ_k − θ*_k)) · X(θ*), check that on
// the branch pose by pose, and write each factor as a link (or several as one, when they fit one
// TSR's frame).
#include "relpos/report/tsr.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "parameter_motion.hpp"

namespace relpos {
namespace {

// One factor: a turn about (point, axis) or a slide along axis, `rate` per unit of θ_k.
struct Factor {
  int param = 0;
  bool turn = false;
  Vector3d axis{0, 0, 1}, point{0, 0, 0};
  double rate = 1.0;
  double lo = 0.0, hi = 0.0;  // the range of rate·(θ_k − θ*_k): the link's bound
};

Isometry3d exponential(const Factor& f, double x) {  // x = rate·(θ_k − θ*_k)
  Isometry3d T = Isometry3d::Identity();
  if (f.turn) {
    T.linear() = Eigen::AngleAxisd(x, f.axis).toRotationMatrix();
    T.translation() = f.point - T.linear() * f.point;
  } else {
    T.translation() = f.axis * x;
  }
  return T;
}

Isometry3d product(const std::vector<Factor>& order, const Params& theta, const Params& at,
                   const Isometry3d& X_at) {
  Isometry3d X = Isometry3d::Identity();
  for (const Factor& f : order) X = X * exponential(f, f.rate * (theta[f.param] - at[f.param]));
  return X * X_at;
}

// Parameters drawn over the chain's box (an unbounded length within ±window of θ*), with the
// corners of the bounded ones first: where a wrong order shows most.
std::vector<Params> checkPoints(const Manifold& m, const Params& at, double window) {
  const int n = m.dof();
  std::vector<Params> out;
  auto range = [&](int i, double* lo, double* hi) {
    const Parameter p = m.parameter(i);
    *lo = std::isfinite(p.min) ? p.min : at[i] - window;
    *hi = std::isfinite(p.max) ? p.max : at[i] + window;
  };
  for (int corner = 0; corner < (1 << n); ++corner) {
    Params t = at;
    for (int i = 0; i < n; ++i) {
      double lo, hi;
      range(i, &lo, &hi);
      t[i] = (corner >> i) & 1 ? hi : lo;
    }
    out.push_back(t);
  }
  std::mt19937_64 rng(0x75725f74737221ull);  // fixed: the same verdict every run
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 48; ++k) {
    Params t = at;
    for (int i = 0; i < n; ++i) {
      double lo, hi;
      range(i, &lo, &hi);
      t[i] = lo + (hi - lo) * u(rng);
    }
    out.push_back(t);
  }
  return out;
}

// Whether the product in `order` is the branch at every check point, to rounding: 1e-9 of the
// problem's size and 1e-9 rad (a wrong order or a parameter that is no fixed screw is off by
// about the motion itself).
bool isTheBranch(const Manifold& m, const std::vector<Factor>& order, const Params& at,
                 const Isometry3d& X_at, const std::vector<Params>& points, double scale) {
  for (const Params& t : points) {
    const Isometry3d X = m.pose(t), Y = product(order, t, at, X_at);
    if (!((X.translation() - Y.translation()).norm() <= 1e-9 * scale) ||
        !(rotationDistance(X.linear(), Y.linear()) <= 1e-9))
      return false;
  }
  return true;
}

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
std::vector<TsrLink> linkPerFactor(const std::vector<Factor>& order, const Isometry3d& X_at) {
  std::vector<TsrLink> chain;
  std::vector<Isometry3d> frames;
  for (const Factor& f : order) {
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
    chain[k].Tw_e =
        frames[k].inverse() * (k + 1 < chain.size() ? frames[k + 1] : Isometry3d(X_at));
  return chain;
}

// The whole product as one TSR when it fits one frame: slides along mutually perpendicular
// directions, then at most one turn, about an axis each slide is along or across, as
// T0_w·Trans(x, y, z)·Rz(yaw)·Tw_e applies them (z: the turn's axis).
bool oneLink(const std::vector<Factor>& order, const Isometry3d& X_at, TsrLink* link) {
  std::vector<const Factor*> slides;
  const Factor* turn = nullptr;
  for (const Factor& f : order) {
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
  const Factor* across = nullptr;
  for (const Factor* s : slides) {
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
  for (const Factor* s : slides) {
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
    xform.linear() = (Eigen::AngleAxisd(v[5], Vector3d::UnitZ()) *
                      Eigen::AngleAxisd(v[4], Vector3d::UnitY()) *
                      Eigen::AngleAxisd(v[3], Vector3d::UnitX()))
                         .toRotationMatrix();
    X = X * chain[k].T0_w * xform * chain[k].Tw_e;
  }
  return X;
}

TsrExport tsrChainOf(const Problem& problem, const Branch& branch, const Params& at,
                     double window) {
  TsrExport out;
  const Manifold& m = *branch.manifold;
  const int n = m.dof();
  const Isometry3d X_at = m.pose(at);
  const double scale = std::max({1.0, problem.lengthScale(), X_at.translation().norm()});
  std::vector<Factor> slides, turns;  // the parameters' factors, slides and turns apart
  for (int i = 0; i < n; ++i) {
    const Parameter p = m.parameter(i);
    // A wide step: for a fixed screw the motion between the two poses is exact (less rounding
    // than a small one); for anything else the check below fails.
    const ParameterMotion mo = detail::motionAlong(m, at, i, 0.05, scale);
    if (mo.type != ParameterMotion::Type::kRotation &&
        mo.type != ParameterMotion::Type::kTranslation) {
      out.why = std::string("parameter ") + p.name + " is " +
                (mo.type == ParameterMotion::Type::kScrew ? "a screw (a turn that advances)"
                                                          : "no motion of its own") +
                ", which no TSR bound makes";
      return out;
    }
    Factor f;
    f.param = i;
    f.turn = mo.type == ParameterMotion::Type::kRotation;
    f.axis = mo.axis;
    f.point = mo.point;
    f.rate = mo.rate;
    double lo = p.min, hi = p.max;
    if (p.periodic) lo = -kPi, hi = kPi;
    if (!std::isfinite(lo)) lo = at[i] - window, out.windowed = true;
    if (!std::isfinite(hi)) hi = at[i] + window, out.windowed = true;
    f.lo = f.rate * (lo - at[i]);
    f.hi = f.rate * (hi - at[i]);
    (f.turn ? turns : slides).push_back(f);
  }
  // Every order of the factors, slides first in the first ones tried (they commute with one
  // another, and a product of slides then one turn is a single TSR); a serial chain (a turn, a
  // slide whose direction it carries, …) needs its own order. At most 6! orders.
  std::vector<Factor> factors = slides;
  factors.insert(factors.end(), turns.begin(), turns.end());
  const std::vector<Params> points = checkPoints(m, at, window);
  std::vector<int> perm(factors.size());
  std::iota(perm.begin(), perm.end(), 0);
  do {
    std::vector<Factor> order;
    for (int k : perm) order.push_back(factors[static_cast<std::size_t>(k)]);
    if (isTheBranch(m, order, at, X_at, points, scale)) {
      TsrLink single;
      out.chain = oneLink(order, X_at, &single) ? std::vector<TsrLink>{single}
                                                : linkPerFactor(order, X_at);
      out.exact = true;
      return out;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  out.why = "the branch is not a product of turns about fixed lines and slides along fixed "
            "directions, one per parameter, in any order";
  out.windowed = false;
  return out;
}

}  // namespace relpos
