// Branches as products of screws (relpos/report/pose_model.hpp): find an order of the parameters
// in which the branch is a product of exponentials — rigid, or separable (the orientation's turns
// and one point's motions apart) — and check it on the branch pose by pose.
#include "screw_product.hpp"

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

#include "parameter_motion.hpp"

namespace relpos {
namespace detail {

Isometry3d product(const std::vector<ScrewFactor>& order, const Params& theta, const Params& at,
                   const Isometry3d& X_at, const Vector3d& pivot) {
  Matrix3d R = Matrix3d::Identity();
  Isometry3d P = Isometry3d::Identity();
  for (const ScrewFactor& f : order) {
    const Isometry3d E = exponential(f, f.rate * (theta[f.param] - at[f.param]));
    if (f.orients) R = R * E.linear();
    if (f.moves) P = P * E;
  }
  Isometry3d X = Isometry3d::Identity();
  X.linear() = R * X_at.linear();
  X.translation() = P * (X_at * pivot) - X.linear() * pivot;
  return X;
}

void boxOf(const Parameter& p, double at, double window, double* lo, double* hi) {
  *lo = p.periodic ? -kPi : p.min;
  *hi = p.periodic ? kPi : p.max;
  if (!std::isfinite(*lo)) *lo = at - window;
  if (!std::isfinite(*hi)) *hi = at + window;
}

std::vector<Params> checkPoints(const Manifold& m, const Params& at, double window) {
  const int n = m.dof();
  std::array<double, kMaxDof> lo{}, hi{};
  for (int i = 0; i < n; ++i) boxOf(m.parameter(i), at[i], window, &lo[i], &hi[i]);
  std::vector<Params> out;
  for (int corner = 0; corner < (1 << n); ++corner) {
    Params t = at;
    for (int i = 0; i < n; ++i) t[i] = (corner >> i) & 1 ? hi[i] : lo[i];
    out.push_back(t);
  }
  std::mt19937_64 rng(0x75725f74737221ull);  // fixed: the same verdict every run
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 48; ++k) {
    Params t = at;
    for (int i = 0; i < n; ++i) t[i] = lo[i] + (hi[i] - lo[i]) * u(rng);
    out.push_back(t);
  }
  return out;
}

// Whether pose Y is X to rounding: 1e-9 of the problem's size and 1e-9 rad (a wrong order or a
// parameter that is no fixed screw is off by about the motion itself). `part`: both, or only the
// orientation (1) or the position of the point `pivot` of the object (2).
static bool samePose(const Isometry3d& X, const Isometry3d& Y, const Vector3d& pivot, double scale,
                     int part = 3) {
  return !((part & 2) && !((X * pivot - Y * pivot).norm() <= 1e-9 * scale)) &&
         !((part & 1) && !(rotationDistance(X.linear(), Y.linear()) <= 1e-9));
}

// Whether the product in `order` is the branch's `part` at every check point.
static bool isTheBranch(const Manifold& m, const std::vector<ScrewFactor>& order, const Params& at,
                        const Isometry3d& X_at, const Vector3d& pivot,
                        const std::vector<Params>& points, double scale, int part) {
  for (const Params& t : points)
    if (!samePose(m.pose(t), product(order, t, at, X_at, pivot), pivot, scale, part)) return false;
  return true;
}

// Factor f's bounds: the range of rate·(θ − θ*) over its parameter's box (lo ≤ hi); *windowed
// set when an unbounded length was boxed to ± window.
static void boundFactor(ScrewFactor& f, const Parameter& p, double at, double window,
                        bool* windowed) {
  double lo, hi;
  boxOf(p, at, window, &lo, &hi);
  if (!p.periodic && !(std::isfinite(p.min) && std::isfinite(p.max))) *windowed = true;
  f.lo = f.rate * (lo - at), f.hi = f.rate * (hi - at);
  if (f.lo > f.hi) std::swap(f.lo, f.hi);
}

// The first order of `factors` (all of them tried) whose product is the branch's `part`.
static std::optional<std::vector<ScrewFactor>> firstOrder(const Manifold& m,
                                                          const std::vector<ScrewFactor>& factors,
                                                          const Params& at, const Isometry3d& X_at,
                                                          const Vector3d& pivot,
                                                          const std::vector<Params>& points,
                                                          double scale, int part) {
  std::vector<int> perm(factors.size());
  std::iota(perm.begin(), perm.end(), 0);
  do {
    std::vector<ScrewFactor> order;
    for (int k : perm) order.push_back(factors[static_cast<std::size_t>(k)]);
    if (isTheBranch(m, order, at, X_at, pivot, points, scale, part)) return order;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return std::nullopt;
}

Vector3d pivotOf(const Manifold& m, const Params& at, const Isometry3d& X_at, double scale) {
  const Vector3d origin = X_at.translation();
  Matrix3d A = Matrix3d::Zero();
  Vector3d b = Vector3d::Zero();
  std::vector<std::pair<Vector3d, Vector3d>> lines;
  for (int i = 0; i < m.dof(); ++i) {
    const ParameterMotion mo = detail::motionAlong(m, at, X_at.translation(), i, 0.05, scale);
    if (mo.type == ParameterMotion::Type::kTranslation || mo.type == ParameterMotion::Type::kNone)
      continue;
    if (mo.type != ParameterMotion::Type::kRotation) return Vector3d::Zero();
    const Matrix3d across = Matrix3d::Identity() - mo.axis * mo.axis.transpose();
    A += across, b += across * mo.point;
    lines.emplace_back(mo.point, mo.axis);
  }
  if (lines.empty()) return Vector3d::Zero();
  // The point nearest every axis (the least-norm move from the origin where they are parallel).
  const Vector3d c =
      origin + Eigen::CompleteOrthogonalDecomposition<Matrix3d>(A).solve(b - A * origin);
  for (const auto& [q, a] : lines)
    if (!((c - q - (c - q).dot(a) * a).norm() <= 1e-9 * scale)) return Vector3d::Zero();
  return X_at.inverse() * c;
}

std::optional<std::vector<ScrewFactor>> separableProduct(const Manifold& m, const Params& at,
                                                         const Isometry3d& X_at,
                                                         const Vector3d& pivot,
                                                         const std::vector<Params>& points,
                                                         double scale) {
  std::vector<ScrewFactor> turns, moves;
  for (int i = 0; i < m.dof(); ++i) {
    Params ta, tb;
    if (!stepAround(m, at, i, 0.05, &ta, &tb)) continue;  // motionAlong's wide step
    const double span = tb[i] - ta[i];
    const Isometry3d Xa = m.pose(ta), Xb = m.pose(tb);
    const Eigen::AngleAxisd turn(Matrix3d(Xb.linear() * Xa.linear().transpose()));
    if (turn.angle() > 1e-12) {
      ScrewFactor f;
      f.param = i, f.turn = true, f.moves = false;
      f.axis = turn.axis(), f.rate = turn.angle() / span;
      turns.push_back(f);
    }
    const Vector3d p0 = Xa * pivot, p1 = X_at * pivot, p2 = Xb * pivot;
    const Vector3d chord = p2 - p0;
    if (!(chord.norm() > 1e-12 * scale)) continue;
    ScrewFactor f;
    f.param = i, f.orients = false;
    const Vector3d u = p1 - p0, v = p2 - p1, n = u.cross(v);
    if (n.norm() <= 1e-9 * u.norm() * v.norm()) {  // on a line
      f.axis = chord.normalized(), f.rate = chord.norm() / span;
    } else {  // on a circle: its centre (the circumcentre of p0, p1, p2) and axis
      const Vector3d w = p2 - p0;
      const Vector3d c = p0 + (w.squaredNorm() * n.cross(u) + u.squaredNorm() * w.cross(n)) /
                                  (2.0 * n.squaredNorm());
      f.turn = true;
      f.axis = n.normalized();
      f.point = c;
      const Vector3d r0 = p0 - c, r2 = p2 - c;
      f.rate = std::atan2(f.axis.dot(r0.cross(r2)), r0.dot(r2)) / span;
    }
    if (!std::isfinite(f.rate) || !f.point.allFinite()) return std::nullopt;
    moves.push_back(f);
  }
  auto R = firstOrder(m, turns, at, X_at, pivot, points, scale, 1);
  if (!R) return std::nullopt;
  auto t = firstOrder(m, moves, at, X_at, pivot, points, scale, 2);
  if (!t) return std::nullopt;
  R->insert(R->end(), t->begin(), t->end());
  return R;
}

}  // namespace detail

using detail::checkPoints;
using detail::pivotOf;
using detail::separableProduct;

Isometry3d exponential(const ScrewFactor& f, double x) {
  Isometry3d T = Isometry3d::Identity();
  if (f.turn) {
    T.linear() = Eigen::AngleAxisd(x, f.axis).toRotationMatrix();
    T.translation() = f.point - T.linear() * f.point + f.pitch * x * f.axis;
  } else {
    T.translation() = f.axis * x;
  }
  return T;
}

std::optional<std::vector<ScrewFactor>> screwProduct(const Problem& problem, const Branch& branch,
                                                     const Params& at, double window, bool screws,
                                                     std::string* why, bool* windowed) {
  const Manifold& m = *branch.manifold;
  const int n = m.dof();
  const Isometry3d X_at = m.pose(at);
  const double scale = std::max({1.0, problem.lengthScale(), X_at.translation().norm()});
  *windowed = false;
  std::vector<ScrewFactor> slides, turns;  // the parameters' factors, slides and turns apart
  for (int i = 0; i < n; ++i) {
    const Parameter p = m.parameter(i);
    // A wide step: for a fixed screw the motion between the two poses is exact (less rounding
    // than a small one); for anything else the check below fails.
    const ParameterMotion mo = detail::motionAlong(m, at, X_at.translation(), i, 0.05, scale);
    const bool usable = mo.type == ParameterMotion::Type::kRotation ||
                        mo.type == ParameterMotion::Type::kTranslation ||
                        (screws && mo.type == ParameterMotion::Type::kScrew);
    if (!usable) {
      *why = std::string("parameter ") + p.name + " is " +
             (mo.type == ParameterMotion::Type::kScrew ? "a screw (a turn that advances)"
                                                       : "no motion of its own") +
             ", which no TSR bound makes";
      return std::nullopt;
    }
    ScrewFactor f;
    f.param = i;
    f.turn = mo.type != ParameterMotion::Type::kTranslation;
    f.axis = mo.axis;
    f.point = mo.point;
    f.pitch = mo.type == ParameterMotion::Type::kScrew ? mo.pitch : 0.0;
    f.rate = mo.rate;
    detail::boundFactor(f, p, at[i], window, windowed);
    (f.turn ? turns : slides).push_back(f);
  }
  // Every order of the factors, slides first in the first ones tried (they commute with one
  // another, and a product of slides then one turn is a single TSR); a serial chain (a turn, a
  // slide whose direction it carries, …) needs its own order. At most 6! orders.
  std::vector<ScrewFactor> factors = slides;
  factors.insert(factors.end(), turns.begin(), turns.end());
  if (auto order = detail::firstOrder(m, factors, at, X_at, Vector3d::Zero(),
                                      checkPoints(m, at, window), scale, 3))
    return order;
  *why =
      "the branch is not a product of turns about fixed lines and slides along fixed "
      "directions, one per parameter, in any order";
  *windowed = false;
  return std::nullopt;
}

std::optional<std::vector<ScrewFactor>> rigidProduct(const Problem& problem, const Branch& branch,
                                                     const Params& at, double window,
                                                     std::string* why, bool* windowed) {
  if (auto order = screwProduct(problem, branch, at, window, false, why, windowed)) return order;
  const Manifold& m = *branch.manifold;
  const Isometry3d X_at = m.pose(at);
  const double scale = std::max({1.0, problem.lengthScale(), X_at.translation().norm()});
  const std::vector<Params> points = checkPoints(m, at, window);
  const Vector3d pivot = pivotOf(m, at, X_at, scale);
  const auto separable = separableProduct(m, at, X_at, pivot, points, scale);
  if (!separable) return std::nullopt;  // *why: screwProduct's
  std::vector<ScrewFactor> orients, moves;
  for (const ScrewFactor& f : *separable) (f.orients ? orients : moves).push_back(f);
  // Rigid, with its bounds: a turn about `through` (or a slide) over the parameter's box.
  bool open = false;
  auto rigid = [&](ScrewFactor f, const Vector3d& through) {
    f.orients = f.moves = true;
    if (f.turn) f.point = through;
    detail::boundFactor(f, m.parameter(f.param), at[f.param], window, &open);
    return f;
  };
  // The pivot slides, or turns about one axis first (a fingertip around a can); the orientation
  // then turns freely about that axis too, so the turn carries the whole object and the
  // orientation's own turn about it, less the carried one, is again a full turn.
  const auto turning =
      std::find_if(moves.begin(), moves.end(), [](const ScrewFactor& f) { return f.turn; });
  const bool carried = turning != moves.end();
  if (carried) {
    const bool first =
        turning == moves.begin() &&
        std::none_of(moves.begin() + 1, moves.end(), [](const ScrewFactor& f) { return f.turn; });
    // A whole turn: a periodic parameter whose rate takes it round at least once.
    const bool free_about_it = !orients.empty() && m.parameter(orients[0].param).periodic &&
                               std::abs(orients[0].rate) >= 1.0 - 1e-9 &&
                               std::abs(orients[0].axis.dot(turning->axis)) > 1.0 - 1e-12;
    if (!first || !free_about_it) {
      *why =
          "the branch's position turns about an axis its orientation does not turn freely "
          "about, which no TSR chain makes";
      return std::nullopt;
    }
  }
  const Vector3d s_at = X_at * pivot;
  std::vector<ScrewFactor> chain;
  for (const ScrewFactor& f : moves) chain.push_back(rigid(f, f.point));
  for (std::size_t k = 0; k < orients.size(); ++k) {
    ScrewFactor f = rigid(orients[k], s_at);
    if (k == 0 && carried) {  // the orientation's turn less the carried one: any angle
      f.axis = turning->axis;
      f.rate = orients[0].rate * orients[0].axis.dot(turning->axis);
      f.lo = -kPi, f.hi = kPi;
    }
    chain.push_back(f);
  }
  // Checked on the branch: the carried turn's angle taken from the orientation's.
  for (const Params& t : points) {
    Isometry3d X = Isometry3d::Identity();
    double carried_angle = 0.0;
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const ScrewFactor& f = chain[k];
      double x = f.rate * (t[f.param] - at[f.param]);
      if (carried && k == 0) carried_angle = x;
      if (carried && k == moves.size()) x -= carried_angle;
      X = X * exponential(f, x);
    }
    if (!detail::samePose(m.pose(t), X * X_at, Vector3d::Zero(), scale)) {
      *why = "the branch's separable product is no chain of rigid turns and slides";
      return std::nullopt;
    }
  }
  *windowed = open;
  return chain;
}

}  // namespace relpos
