// Compiled with -frounding-math (tests/CMakeLists.txt): Boost.Interval switches the rounding mode
// for every bound, and the compiler must not fold or reorder across that.
#include "interval_check.hpp"

#include <Eigen/Dense>
#include <array>
#include <boost/numeric/interval.hpp>
#include <cmath>
#include <limits>
#include <vector>

namespace relpos::test {
namespace {

using I = boost::numeric::interval<double>;
constexpr int kMax = 6;

// Forward-mode derivative over intervals: the value and the partials in up to six unknowns, each
// an enclosure over the box. Evaluating at the box gives the interval Jacobian Krawczyk needs.
struct D {
  I v{0.0};
  std::array<I, kMax> g{};
};
D constant(I c) {
  D d;
  d.v = c;
  for (I& x : d.g) x = I(0.0);
  return d;
}
D operator+(const D& a, const D& b) {
  D r;
  r.v = a.v + b.v;
  for (int k = 0; k < kMax; ++k) r.g[k] = a.g[k] + b.g[k];
  return r;
}
D operator-(const D& a, const D& b) {
  D r;
  r.v = a.v - b.v;
  for (int k = 0; k < kMax; ++k) r.g[k] = a.g[k] - b.g[k];
  return r;
}
D operator*(const D& a, const D& b) {
  D r;
  r.v = a.v * b.v;
  for (int k = 0; k < kMax; ++k) r.g[k] = a.g[k] * b.v + a.v * b.g[k];
  return r;
}
// f(s) with enclosures F of f and Fp of f' over the interval s.v: value F, chain rule Fp·s'.
D apply(const D& s, I F, I Fp) {
  D r;
  r.v = F;
  for (int k = 0; k < kMax; ++k) r.g[k] = Fp * s.g[k];
  return r;
}

using V = std::array<D, 3>;
V add(const V& a, const V& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V sub(const V& a, const V& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V scale(const D& s, const V& a) { return {s * a[0], s * a[1], s * a[2]}; }
D dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V constantV(const std::array<I, 3>& c) { return {constant(c[0]), constant(c[1]), constant(c[2])}; }

// sin θ/θ and (1 − cos θ)/θ² as series in s = θ² = |ω|², and their derivatives in s: alternating
// series whose terms decrease for s < 1, so each lies between two consecutive partial sums.
I hull0(I x) { return boost::numeric::hull(I(0.0), x); }
D sincA(const D& s) {
  return apply(s, I(1.0) - s.v / 6.0 + hull0(s.v * s.v / 120.0), I(-1.0 / 6) + hull0(s.v / 60.0));
}
D cosB(const D& s) {
  return apply(s, I(0.5) - s.v / 24.0 + hull0(s.v * s.v / 720.0),
               I(-1.0 / 24) + hull0(s.v / 360.0));
}

// A double taken as exact data.
std::array<I, 3> exact(const Vector3d& v) { return {I(v.x()), I(v.y()), I(v.z())}; }
// A rounded value (std::cos of a value, a normalised direction): widened by a few ulps.
I widened(double x) {
  const double e = 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(x));
  return I(x - e, x + e);
}
I cosOf(double v) { return widened(std::cos(v)); }
I sinOf(double v) { return widened(std::sin(v)); }

// The reported rotation's quaternion, normalised in intervals: an exactly orthonormal enclosure
// of the reported rotation (whose double matrix is orthonormal only to its rounding).
std::array<std::array<I, 3>, 3> rotationEnclosure(const Matrix3d& R) {
  const Quaterniond q(R);
  const I n =
      sqrt(I(q.w()) * I(q.w()) + I(q.x()) * I(q.x()) + I(q.y()) * I(q.y()) + I(q.z()) * I(q.z()));
  const I w = I(q.w()) / n, x = I(q.x()) / n, y = I(q.y()) / n, z = I(q.z()) / n;
  return {{{1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)},
           {2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)},
           {2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)}}};
}

struct Chart {
  std::array<std::array<I, 3>, 3> R0;
  std::array<I, 3> t0;
  // Unknown k moves (ω, δt) along column k of basis (6 × n).
  Eigen::Matrix<double, 6, Eigen::Dynamic> basis;
};

struct Placed {
  V omega, dt;
};

// The mobile point b (mobile frame) in world coordinates at the chart's point: exp([ω]×) R0 b +
// t0 + δt, with exp([ω]×) c = c + A ω×c + B ω×(ω×c).
V placePoint(const Chart& c, const Placed& x, const D& A, const D& B, const Vector3d& b,
             bool is_direction) {
  std::array<I, 3> r0b;
  for (int i = 0; i < 3; ++i) r0b[i] = c.R0[i][0] * b.x() + c.R0[i][1] * b.y() + c.R0[i][2] * b.z();
  const V v = constantV(r0b);
  const V wv = cross(x.omega, v);
  V out = add(add(v, scale(A, wv)), scale(B, cross(x.omega, wv)));
  if (!is_direction) out = add(add(out, constantV(c.t0)), x.dt);
  return out;
}

// One constraint as a polynomial equation in the placed features (docs/spec.md §1.9):
// squared distances minus squared values, dot products minus cosines (times the directions'
// lengths, which the rounding of a normalised double leaves off 1). False when unsupported.
bool equation(const InputConstraint& c, const Isometry3d& X_WF, const Chart& ch, const Placed& x,
              const D& A, const D& B, D* e, std::string* why) {
  using K = FeatureKind;
  if (!c.has_value) {
    *why = "a range constraint";
    return false;
  }
  // The fixed pose's entries are the problem's data; the products are enclosed, not rounded.
  auto placeFixed = [&](const Vector3d& v, bool is_direction) {
    std::array<I, 3> w;
    for (int i = 0; i < 3; ++i) {
      w[i] = is_direction ? I(0.0) : I(X_WF.translation()[i]);
      for (int j = 0; j < 3; ++j) w[i] += I(X_WF.linear()(i, j)) * v[j];
    }
    return constantV(w);
  };
  auto fixedPoint = [&](const Feature& f) { return placeFixed(f.point, false); };
  auto fixedDir = [&](const Feature& f) { return placeFixed(f.direction, true); };
  auto mobilePoint = [&](const Feature& f) { return placePoint(ch, x, A, B, f.point, false); };
  auto mobileDir = [&](const Feature& f) { return placePoint(ch, x, A, B, f.direction, true); };
  const bool fixed_point = c.fixed.kind == K::kPoint, mobile_point = c.mobile.kind == K::kPoint;
  const I v(c.value);
  if (c.type == "distance" && (fixed_point || mobile_point)) {
    const Feature& pf = mobile_point ? c.mobile : c.fixed;
    const Feature& of = mobile_point ? c.fixed : c.mobile;
    const V p = mobile_point ? mobilePoint(pf) : fixedPoint(pf);
    const V a = mobile_point ? fixedPoint(of) : mobilePoint(of);
    const V d = mobile_point ? fixedDir(of) : mobileDir(of);
    if (of.kind == K::kPoint) {
      const V u = sub(p, a);
      *e = dot(u, u) - constant(v * v);
      return true;
    }
    if (of.kind == K::kLine) {
      const V u = cross(sub(p, a), d);
      *e = dot(u, u) - constant(v * v) * dot(d, d);
      return true;
    }
    if (of.kind == K::kPlane) {  // signed: (p − a)·n̂ = v, with |n| enclosed
      const D nn = dot(d, d);
      const I len = sqrt(nn.v);
      D l = apply(nn, len, I(0.5) / len);
      *e = dot(sub(p, a), d) - constant(v) * l;
      return true;
    }
  }
  if (c.type == "angle" && !fixed_point && !mobile_point && c.fixed.kind != K::kCylinder &&
      c.mobile.kind != K::kCylinder) {
    const V f = fixedDir(c.fixed), m = mobileDir(c.mobile);
    const D ff = dot(f, f), mm = dot(m, m), fm = ff * mm;
    const I len = sqrt(fm.v);
    const D l = apply(fm, len, I(0.5) / len);
    // line-plane: arcsin(d̂·n̂) = v; otherwise arccos(·) = v. Both injective on their ranges.
    const I target = c.fixed.kind != c.mobile.kind ? sinOf(c.value) : cosOf(c.value);
    *e = dot(f, m) - constant(target) * l;
    return true;
  }
  *why = "constraint type '" + c.type + "' on " + toString(c.fixed.kind) + "-" +
         toString(c.mobile.kind) + " is not one this check encodes";
  return false;
}

bool evaluate(const Problem& p, const Chart& ch, const std::vector<I>& box, std::vector<D>* F,
              std::string* why) {
  const int n = static_cast<int>(box.size());
  std::array<D, 6> coord;  // (ω, δt) as functions of the unknowns
  for (int r = 0; r < 6; ++r) {
    coord[r] = constant(I(0.0));
    for (int k = 0; k < n; ++k) {
      const double b = ch.basis(r, k);
      if (b == 0.0) continue;
      coord[r].v += I(b) * box[k];
      coord[r].g[k] += I(b);
    }
  }
  const Placed x{{coord[0], coord[1], coord[2]}, {coord[3], coord[4], coord[5]}};
  const D s = dot(x.omega, x.omega);
  if (!(s.v.upper() < 1.0)) {
    *why = "the rotation box is too large for the series enclosure (|ω| must stay below 1)";
    return false;
  }
  const D A = sincA(s), B = cosB(s);
  F->clear();
  for (const InputConstraint& c : p.constraints) {
    D e;
    if (!equation(c, p.fixed.pose, ch, x, A, B, &e, why)) return false;
    F->push_back(e);
  }
  return true;
}

}  // namespace

IntervalVerdict provesSolutionInBox(const Problem& p, const Isometry3d& X_WM,
                                    const IntervalBox& box) {
  IntervalVerdict out;
  Chart ch;
  ch.R0 = rotationEnclosure(X_WM.linear());
  ch.t0 = exact(X_WM.translation());
  std::vector<I> X;
  if (!box.line_quotient) {
    ch.basis = Eigen::Matrix<double, 6, 6>::Identity();
    for (int k = 0; k < 6; ++k)
      X.push_back(k < 3 ? I(-box.angle, box.angle) : I(-box.radius, box.radius));
  } else {
    const Feature* line = nullptr;
    for (const InputConstraint& c : p.constraints)
      if (c.mobile.kind == FeatureKind::kLine) line = &c.mobile;
    if (!line) {
      out.why = "line_quotient without a mobile line";
      return out;
    }
    // Two directions across the world line: rotations about them and shifts along them move it.
    const Vector3d u = (X_WM.linear() * line->direction).normalized();
    const Vector3d e1 = u.unitOrthogonal(), e2 = u.cross(e1);
    ch.basis = Eigen::Matrix<double, 6, 4>::Zero();
    ch.basis.block<3, 1>(0, 0) = e1;
    ch.basis.block<3, 1>(0, 1) = e2;
    ch.basis.block<3, 1>(3, 2) = e1;
    ch.basis.block<3, 1>(3, 3) = e2;
    // Rotating about an axis through the origin also shifts a line far from it: the rotation's
    // centre is the line's foot point, so translations are measured there.
    const Vector3d a = X_WM * line->point, foot = a - a.dot(u) * u;
    ch.basis.block<3, 1>(3, 0) = -e1.cross(foot);
    ch.basis.block<3, 1>(3, 1) = -e2.cross(foot);
    for (int k = 0; k < 4; ++k)
      X.push_back(k < 2 ? I(-box.angle, box.angle) : I(-box.radius, box.radius));
  }
  const int n = static_cast<int>(X.size());
  if (static_cast<int>(p.constraints.size()) != n) {
    out.why =
        std::to_string(p.constraints.size()) + " equations in " + std::to_string(n) + " unknowns";
    return out;
  }
  for (const I& x : X)
    if (!(x.upper() > 0.0)) {
      out.why = "an empty box (radius and angle must be positive)";
      return out;
    }
  // F at the box's centre (a point interval) and the interval Jacobian over the whole box.
  std::vector<D> Fc, FX;
  if (!evaluate(p, ch, std::vector<I>(n, I(0.0)), &Fc, &out.why)) return out;
  if (!evaluate(p, ch, X, &FX, &out.why)) return out;
  Eigen::MatrixXd mid(n, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) mid(i, k) = median(FX[i].g[k]);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(mid);
  if (!lu.isInvertible()) {
    out.why = "the Jacobian's midpoint is singular";
    return out;
  }
  const Eigen::MatrixXd Y = lu.inverse();
  // K(X) = −Y F(c) + (I − Y J(X)) X, with c = 0; K ⊂ int X proves one root in X.
  for (int i = 0; i < n; ++i) {
    I k(0.0);
    for (int j = 0; j < n; ++j) {
      k -= I(Y(i, j)) * Fc[j].v;
      I m(i == j ? 1.0 : 0.0);
      for (int l = 0; l < n; ++l) m -= I(Y(i, l)) * FX[l].g[j];
      k += m * X[j];
    }
    if (!(k.lower() > X[i].lower() && k.upper() < X[i].upper())) {
      out.why = "K(X) is not inside the box (coordinate " + std::to_string(i) + ": [" +
                std::to_string(k.lower()) + ", " + std::to_string(k.upper()) + "] vs ±" +
                std::to_string(X[i].upper()) + ")";
      return out;
    }
  }
  out.proven = true;
  return out;
}

IntervalBox certificateBox(double radius, double angle, bool line_quotient) {
  return {radius, angle > 0 ? angle / std::sqrt(3.0) : radius / 3.0, line_quotient};
}

IntervalVerdict provesSolutionWithin(const Problem& p, const Isometry3d& X_WM, IntervalBox box) {
  const IntervalVerdict first = provesSolutionInBox(p, X_WM, box);
  if (first.proven) return first;
  for (int shrink = 1; shrink <= 12; ++shrink) {
    box.radius /= 10;
    box.angle /= 10;
    if (provesSolutionInBox(p, X_WM, box).proven) return {true, ""};
  }
  return first;
}

}  // namespace relpos::test
