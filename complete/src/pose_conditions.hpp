#pragma once
// The constraints of a problem as scalar conditions on the pose, for the numeric stage's sets of
// poses (chart.hpp): each fundamental constraint (core/fundamental.hpp) one or a few smooth
// functions g of the pose, an equation g = lo (lo == hi) or an inequality lo ≤ g ≤ hi. Smooth
// where the set is: a distance is squared (a range of distances stays a range), a zero distance
// or a parallelism is two or three linear conditions (a squared one would be singular on its
// whole set), an angle is its cosine.
//
// Everything is normalised: world points about the fixed features' centre, mobile points about
// the mobile ones', lengths over the problem's size, so that a pose is (R, t) with
// t = (R·c_m + T − c_w) / L and lengths, rotations and the tolerances compare as numbers ~1.
// The evaluation is one template over the scalar (double, the forward derivatives of
// forward_dual.hpp, the interval type): the rotation as the rational map of the quaternion
// (1, a, b, c) and the translation, six coordinates y = (a, b, c, t) about a base pose.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "forward_dual.hpp"
#include "relpos/complete/study.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/registry.hpp"

namespace relpos::complete::detail {

// What the conditions' and the exclusion's open bounds are.
inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class ConditionKind : unsigned char {
  kPointPoint,  // |x − q|², x = R p + t the mobile point
  kPointLine,  // |v|² − (v·d)², v = x − q: the mobile point's squared distance to a fixed line
  kLinePoint,    // the same from the fixed point q to the mobile line (p, u)
  kPointPlane,   // (x − q)·d: the mobile point's offset from a fixed plane
  kPlanePoint,   // (q − x)·(R u): the fixed point's offset from the mobile plane (p, u)
  kCosine,       // (R u)·d
  kSkew,         // (x − q)·(R u × d): zero when the mobile line (p, u) meets the fixed (q, d)
  kSkewSquared,  // ((x − q)·n)² − k |n|², n = R u × d: the skew distance's square minus k
};

// A condition's stored vector as Eigen's.
inline Vector3d vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// The mask bit of input constraint `source` (constraints from 64 on share bit source mod 64).
inline SourceMask sourceBit(int source) { return SourceMask{1} << (source % 64); }

struct Condition {
  ConditionKind kind = ConditionKind::kPointPoint;
  std::array<double, 3> p{}, u{};  // mobile point and direction (mobile frame, normalised)
  std::array<double, 3> q{}, d{};  // fixed point and direction (world, normalised)
  double k = 0.0;                  // kSkewSquared only
  double lo = 0.0, hi = 0.0;       // equation: lo == hi; an inequality may have an infinite side
  int source = 0;                  // the input constraint
  bool equation() const { return lo == hi; }
};

// One way the constraints can hold (an "either" orientation is two), normalised as above
// (the polynomial encodings' normalisation type, study.hpp: scaledPose and poseOf map poses).
struct ConditionSystem {
  std::vector<Condition> equations, inequalities;
  Normalisation frame;
};

// Every alternative of the problem's constraints (at most `max_alternatives`), or false with the
// reason: a plugin's type, a constraint no fundamental expresses, a custom kind.
bool buildConditionSystems(const Problem& problem, const Registry& registry,
                           std::vector<ConditionSystem>* out, std::string* why,
                           int max_alternatives = 8);

// The largest magnitude of the problem's coordinates and values as placed, and of the mobile
// object's initial pose (NaN for a NaN): beyond 1e100 a pose's squared distances overflow.
double largestMagnitude(const Problem& p);

// The worst violation of any input constraint at pose X, in tolerances (infinity: unknown, or a
// type without a violation function): what every branch of the stage is checked with (§6.5).
double worstViolation(const Problem& problem, const Registry& registry, const Tolerance& tol,
                      const Isometry3d& X);

// How far condition c's value may be from its target for the constraint to be off by at most a
// length δ (normalised) or an angle α, to first order in the condition's own units: a length δ;
// a squared distance d² by 2·d·δ; a cosine cos θ by α·sin θ (an angle near 0 or π moves its
// cosine least). The value is the condition's own (an equation's), lo. A skew condition's is
// the length's, an upper bound only (its value moves by |n|·δ, |n| ≤ 1: set_stage.cpp reads |n|
// at the pose where it must be a tolerance).
double toleranceInUnits(const Condition& c, double length, double angle);
// The same, a skew condition's made exact at rotation R (of the condition's frame): h = (x − q)·n
// with |n| the sine of the lines' angle moves by |n|·δ for a distance δ, h² − k|n|² by
// 2·√k·|n|²·δ; |n| read at R, less a 10 % margin for poses near it.
double toleranceAt(const Condition& c, const Matrix3d& R, double length, double angle);

// The conditions with their fixed data moved into the frame of the base pose (R0, t0): then the
// pose R0·Q(a, b, c), t0 + R0·τ has the coordinates y = (a, b, c, τ), and y = 0 is the base.
Condition inBaseFrame(const Condition& c, const Matrix3d& R0, const Vector3d& t0);
// Every condition of `in` so moved, into `out` (cleared first).
void inBaseFrame(const std::vector<Condition>& in, const Matrix3d& R0, const Vector3d& t0,
                 std::vector<Condition>* out);

// --- the evaluation, one template for every scalar -----------------------------------------
template <typename T>
struct ScalarOf {
  using type = T;
};
template <typename S>
struct ScalarOf<Dual<S>> {
  using type = S;
};
template <typename T>
T lift(double c) {
  return T(typename ScalarOf<T>::type(c));
}

inline double square(double a) { return a * a; }
template <typename S>
Dual<S> square(const Dual<S>& a) {
  Dual<S> r;
  r.v = square(a.v);
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = a.g[i] * (a.v * S(2.0));
  return r;
}

template <typename T>
using V3 = std::array<T, 3>;

// The base-frame rotation Q(a, b, c) of the quaternion (1, a, b, c), row-major, and the
// translation τ: the pose at coordinates y.
template <typename T>
struct LocalPose {
  std::array<T, 9> Q;
  V3<T> t;
  explicit LocalPose(const std::array<T, 6>& y) {
    const T& a = y[0];
    const T& b = y[1];
    const T& c = y[2];
    const T a2 = square(a), b2 = square(b), c2 = square(c);
    const T one = lift<T>(1.0);
    // One division, then products: the forward derivatives' division costs six quotients, and
    // this runs for every residual of the descent and every Newton step of a chart's pose.
    const T inv = one / (one + a2 + b2 + c2);
    const T inv2 = inv * 2.0;
    const T ab = a * b, ac = a * c, bc = b * c;
    Q[0] = (one + a2 - b2 - c2) * inv;
    Q[1] = (ab - c) * inv2;
    Q[2] = (ac + b) * inv2;
    Q[3] = (ab + c) * inv2;
    Q[4] = (one - a2 + b2 - c2) * inv;
    Q[5] = (bc - a) * inv2;
    Q[6] = (ac - b) * inv2;
    Q[7] = (bc + a) * inv2;
    Q[8] = (one - a2 - b2 + c2) * inv;
    t = {y[3], y[4], y[5]};
  }
  // The base pose y = 0 with its first derivatives, T a forward dual of doubles: Q = I,
  // ∂Q/∂(a, b, c) = 2[e_a,b,c]×, ∂t/∂τ = I — what the constructor computes there, without its
  // arithmetic (the descent takes every Jacobian at its current base).
  struct AtBase {};
  explicit LocalPose(AtBase) {
    for (T& q : Q) q = lift<T>(0.0);
    Q[0] = Q[4] = Q[8] = lift<T>(1.0);
    Q[1].g[2] = -2.0, Q[2].g[1] = 2.0, Q[3].g[2] = 2.0;
    Q[5].g[0] = -2.0, Q[6].g[1] = -2.0, Q[7].g[0] = 2.0;
    t = {T::variable(0.0, 3), T::variable(0.0, 4), T::variable(0.0, 5)};
  }
  V3<T> rotate(const std::array<double, 3>& v) const {
    V3<T> r;
    for (int i = 0; i < 3; ++i) r[i] = Q[3 * i] * v[0] + Q[3 * i + 1] * v[1] + Q[3 * i + 2] * v[2];
    return r;
  }
  V3<T> place(const std::array<double, 3>& p) const {
    V3<T> r = rotate(p);
    for (int i = 0; i < 3; ++i) r[i] = r[i] + t[i];
    return r;
  }
};

template <typename T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <typename T>
T dotd(const V3<T>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <typename T>
V3<T> minus(const V3<T>& a, const std::array<double, 3>& b) {
  return {a[0] - lift<T>(b[0]), a[1] - lift<T>(b[1]), a[2] - lift<T>(b[2])};
}
template <typename T>
T squaredNorm(const V3<T>& a) {
  return square(a[0]) + square(a[1]) + square(a[2]);
}

// g(pose) for condition c (its fixed data in the pose's base frame).
template <typename T>
T evaluate(const Condition& c, const LocalPose<T>& X) {
  switch (c.kind) {
    case ConditionKind::kPointPoint:
      return squaredNorm(minus(X.place(c.p), c.q));
    case ConditionKind::kPointLine: {
      const V3<T> v = minus(X.place(c.p), c.q);
      return squaredNorm(v) - square(dotd(v, c.d));
    }
    case ConditionKind::kLinePoint: {
      const V3<T> v = minus(X.place(c.p), c.q);  // −(q − x): the square does not mind
      return squaredNorm(v) - square(dot(v, X.rotate(c.u)));
    }
    case ConditionKind::kPointPlane:
      return dotd(minus(X.place(c.p), c.q), c.d);
    case ConditionKind::kPlanePoint:
      return -dot(minus(X.place(c.p), c.q), X.rotate(c.u));
    case ConditionKind::kCosine:
      return dotd(X.rotate(c.u), c.d);
    case ConditionKind::kSkew:
    case ConditionKind::kSkewSquared: {
      const V3<T> w = X.rotate(c.u);
      const V3<T> n = {w[1] * c.d[2] - w[2] * c.d[1], w[2] * c.d[0] - w[0] * c.d[2],
                       w[0] * c.d[1] - w[1] * c.d[0]};
      const T h = dot(minus(X.place(c.p), c.q), n);
      if (c.kind == ConditionKind::kSkew) return h;
      return square(h) - squaredNorm(n) * c.k;
    }
  }
  return lift<T>(0.0);
}

}  // namespace relpos::complete::detail
