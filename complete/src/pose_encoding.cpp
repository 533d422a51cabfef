// A problem's constraints as the equations of a PoseFamily member (problem_encoding.hpp). Each
// built-in constraint with an exact value becomes the scalar equations of docs/spec.md §1.9's
// "holds when", in the normalised frames; a zero distance or a coincidence becomes planes
// through the point (a squared distance of 0 is a double root, which no certification proves).
#include <cmath>

#include "encoding_support.hpp"
#include "relpos/complete/problem_encoding.hpp"

namespace relpos::complete {
namespace {

using detail::NormalisedConstraint;
using detail::Slots;
using FK = FeatureKind;
using K = PoseEquationKind;

// Two fixed generic real charts c·e = 1 (the second for a retry: a pose with c·e = 0 is at
// infinity in the first).
const Eigen::Vector4d kCharts[2] = {Eigen::Vector4d(0.8147, -0.4567, 0.6324, 0.3571),
                                    Eigen::Vector4d(0.2785, 0.9058, -0.5469, -0.7431)};

class PoseEncoder {
 public:
  PoseEncoder(PoseEncoding* out, std::string* why, unsigned alternative)
      : alternative_(alternative), out_(out), why_(why), slots_(&out->target) {}

  void chart(const Eigen::Vector4d& c) {
    PoseEquation q{K::kChart, -1, -1, -1, slots_.size()};
    for (int i = 0; i < 4; ++i) out_->target.push_back(c[i]);
    out_->equations.push_back(q);
    out_->equations.push_back({K::kStudy, -1, -1, -1, -1});
  }

  bool add(const InputConstraint& c, const NormalisedConstraint& n);

 private:
  bool refuse(const std::string& what) {
    *why_ = what;
    return false;
  }
  int fixedPoint(const Vector3d& a) { return slots_.shared(Slots::kFixed, Slots::kPoint, a); }
  int mobilePoint(const Vector3d& b) { return slots_.shared(Slots::kMobile, Slots::kPoint, b); }
  int fixedDirection(const Vector3d& u) {
    return slots_.shared(Slots::kFixed, Slots::kDirection, u);
  }
  int mobileDirection(const Vector3d& m) {
    return slots_.shared(Slots::kMobile, Slots::kDirection, m);
  }
  void push(K kind, int fixed, int mobile, int line, double value) {
    out_->equations.push_back({kind, fixed, mobile, line, slots_.value(value)});
  }

  // |p − a| = d for mobile point b, fixed point a.
  void pointPoint(const Vector3d& a, const Vector3d& b, double d) {
    if (d != 0.0) return push(K::kPointPoint, fixedPoint(a), mobilePoint(b), -1, d * d);
    for (int k = 0; k < 3; ++k)  // p = a: on three planes through a
      push(K::kPointPlane, fixedDirection(Vector3d::Unit(k)), mobilePoint(b), -1, a[k]);
  }
  // Mobile point b at signed distance d from fixed plane (a, n).
  void mobilePointPlane(const Vector3d& b, const Vector3d& a, const Vector3d& n, double d) {
    push(K::kPointPlane, fixedDirection(n), mobilePoint(b), -1, d + n.dot(a));
  }
  // Fixed point a at signed distance d from mobile plane (b, m).
  void fixedPointPlane(const Vector3d& a, const Vector3d& b, const Vector3d& m, double d) {
    push(K::kPlanePoint, fixedPoint(a), mobileDirection(m), -1, d + m.dot(b));
  }
  // Mobile point b at distance d from fixed line (a, u).
  void mobilePointLine(const Vector3d& b, const Vector3d& a, const Vector3d& u, double d) {
    if (d != 0.0)
      return push(K::kPointLine, fixedPoint(a), mobilePoint(b), fixedDirection(u), d * d);
    Vector3d n[2];
    detail::normalsAcross(u, &n[0], &n[1]);
    for (const Vector3d& nk : n)
      push(K::kPointPlane, fixedDirection(nk), mobilePoint(b), -1, nk.dot(a));
  }
  // Fixed point a at distance d from mobile line (b, m).
  void fixedPointLine(const Vector3d& a, const Vector3d& b, const Vector3d& m, double d) {
    if (d != 0.0)
      return push(K::kLinePoint, fixedPoint(a), mobilePoint(b), mobileDirection(m), d * d);
    Vector3d n[2];
    detail::normalsAcross(m, &n[0], &n[1]);
    for (const Vector3d& nk : n)
      push(K::kPlanePoint, fixedPoint(a), mobileDirection(nk), -1, nk.dot(b));
  }
  // u · R m = κ.
  void direction(const Vector3d& u, const Vector3d& m, double kappa) {
    push(K::kDirection, fixedDirection(u), mobileDirection(m), -1, kappa);
  }
  // R m ∥ u per orientation: R m on two planes through u, and the sign checked on the roots.
  // Their normals are the ones a point on the line (u) is put on (mobilePointLine, d = 0) with:
  // shared, so that every member keeps the slide along the line a coincidence leaves.
  void parallel(const Vector3d& u, const Vector3d& m, Orientation o) {
    Vector3d n[2];
    detail::normalsAcross(u, &n[0], &n[1]);
    for (const Vector3d& nk : n)
      push(K::kDirection, fixedDirection(nk), mobileDirection(m), -1, 0.0);
    if (o != Orientation::kEither)
      out_->signs.push_back({u, m, o == Orientation::kAligned ? 1.0 : -1.0});
  }

  // Parallel planes, the mobile one at signed distance v along the fixed normal n = σ R m
  // (σ = ±1 per orientation). Read in the mobile frame, m·Rᵀ(a − t) = m·b − σ v, so that its
  // normal is the parallelism's in every member: the fixed normal, independent of R m in a
  // generic member, would turn the position's equation with the spin (and lose roots).
  bool planeOnPlane(const Feature& F, const Feature& M, Orientation o, double v) {
    if (o == Orientation::kEither && v != 0.0) o = choose();  // two subproblems
    parallel(F.direction, M.direction, o);
    const double sigma = o == Orientation::kOpposed ? -1.0 : 1.0;
    push(K::kPlanePoint, fixedPoint(F.point), mobileDirection(M.direction), -1,
         M.direction.dot(M.point) - sigma * v);
    return true;
  }

  // The orientation of the next constraint with two (an "either" that changes the equations):
  // bit k of the encoding's `alternative` for the k-th such constraint.
  Orientation choose() {
    const int k = out_->alternatives++;
    return k < 32 && (alternative_ >> k) & 1u ? Orientation::kOpposed : Orientation::kAligned;
  }

  unsigned alternative_;
  PoseEncoding* out_;
  std::string* why_;
  Slots slots_;
};

bool PoseEncoder::add(const InputConstraint& c, const NormalisedConstraint& n) {
  const Feature& F = n.fixed;
  const Feature& M = n.mobile;
  const double v = n.value;
  const FK f = F.kind, m = M.kind;
  const bool same = f == m;
  if (c.type == "distance") {
    if (f == FK::kPoint && m == FK::kPoint) return pointPoint(F.point, M.point, v), true;
    if (f == FK::kPoint && m == FK::kLine)
      return fixedPointLine(F.point, M.point, M.direction, v), true;
    if (f == FK::kLine && m == FK::kPoint)
      return mobilePointLine(M.point, F.point, F.direction, v), true;
    if (f == FK::kPoint && m == FK::kPlane)
      return fixedPointPlane(F.point, M.point, M.direction, v), true;
    if (f == FK::kPlane && m == FK::kPoint)
      return mobilePointPlane(M.point, F.point, F.direction, v), true;
    if (f == FK::kLine && m == FK::kLine) {
      if (!c.parallel) return refuse("a skew line-line distance is not encoded");
      parallel(F.direction, M.direction, c.orientation);
      // Read at the mobile line (its direction is the parallelism's): every member keeps the
      // lines parallel; a distance 0 is the coincidence's planes through the fixed line.
      if (v == 0.0) return mobilePointLine(M.point, F.point, F.direction, 0.0), true;
      return fixedPointLine(F.point, M.point, M.direction, v), true;
    }
    if (f == FK::kLine && m == FK::kPlane) {
      direction(F.direction, M.direction, 0.0);
      return fixedPointPlane(F.point, M.point, M.direction, v), true;
    }
    if (f == FK::kPlane && m == FK::kLine) {
      direction(F.direction, M.direction, 0.0);
      return mobilePointPlane(M.point, F.point, F.direction, v), true;
    }
    if (f == FK::kPlane && m == FK::kPlane) return planeOnPlane(F, M, c.orientation, v);
  } else if (c.type == "angle") {
    if (same) {  // arccos(u·R m) = v; 0 and π are parallelisms (u·R m = ±1 is a double root)
      if (detail::angleAt(v, 0.0) || detail::angleAt(v, kPi))
        return parallel(F.direction, M.direction,
                        detail::angleAt(v, 0.0) ? Orientation::kAligned : Orientation::kOpposed),
               true;
      return direction(F.direction, M.direction, std::cos(v)), true;
    }
    // line-plane: arcsin(d·n) = v, either role
    if (detail::angleAt(std::abs(v), kPi / 2))
      return parallel(F.direction, M.direction,
                      v > 0 ? Orientation::kAligned : Orientation::kOpposed),
             true;
    return direction(F.direction, M.direction, std::sin(v)), true;
  } else if (c.type == "coincident") {
    if (f == FK::kPoint && m == FK::kPoint) return pointPoint(F.point, M.point, 0.0), true;
    if (f == FK::kPoint && m == FK::kLine)
      return fixedPointLine(F.point, M.point, M.direction, 0.0), true;
    if (f == FK::kLine && m == FK::kPoint)
      return mobilePointLine(M.point, F.point, F.direction, 0.0), true;
    if (f == FK::kPoint && m == FK::kPlane)
      return fixedPointPlane(F.point, M.point, M.direction, 0.0), true;
    if (f == FK::kPlane && m == FK::kPoint)
      return mobilePointPlane(M.point, F.point, F.direction, 0.0), true;
    if (f == FK::kPoint && m == FK::kCylinder)
      return fixedPointLine(F.point, M.point, M.direction, M.radius), true;
    if (f == FK::kCylinder && m == FK::kPoint)
      return mobilePointLine(M.point, F.point, F.direction, F.radius), true;
    if (f == FK::kLine && m == FK::kLine) {
      parallel(F.direction, M.direction, c.orientation);
      return mobilePointLine(M.point, F.point, F.direction, 0.0), true;
    }
    if (f == FK::kPlane && m == FK::kPlane) return planeOnPlane(F, M, c.orientation, 0.0);
    if (f == FK::kLine && m == FK::kPlane) {
      direction(F.direction, M.direction, 0.0);
      return fixedPointPlane(F.point, M.point, M.direction, 0.0), true;
    }
    if (f == FK::kPlane && m == FK::kLine) {
      direction(F.direction, M.direction, 0.0);
      return mobilePointPlane(M.point, F.point, F.direction, 0.0), true;
    }
  } else if (c.type == "parallel") {
    if (same) return parallel(F.direction, M.direction, c.orientation), true;
    return direction(F.direction, M.direction, 0.0), true;
  } else if (c.type == "perpendicular") {
    if (same) return direction(F.direction, M.direction, 0.0), true;
    return parallel(F.direction, M.direction, c.orientation), true;
  } else if (c.type == "tangent") {
    if (f == FK::kCylinder && m == FK::kCylinder) {
      parallel(F.direction, M.direction, Orientation::kEither);
      return fixedPointLine(F.point, M.point, M.direction, F.radius + M.radius), true;
    }
    if ((f == FK::kCylinder && m == FK::kPlane) || (f == FK::kPlane && m == FK::kCylinder)) {
      // The axis at signed distance −r (aligned) or +r (opposed) from the plane.
      const Orientation o = c.orientation == Orientation::kEither ? choose() : c.orientation;
      const double r = f == FK::kCylinder ? F.radius : M.radius;
      const double d = o == Orientation::kAligned ? -r : r;
      direction(F.direction, M.direction, 0.0);
      if (f == FK::kPlane) return mobilePointPlane(M.point, F.point, F.direction, d), true;
      return fixedPointPlane(F.point, M.point, M.direction, d), true;
    }
    return refuse("a tangent to a line is not encoded");
  }
  return refuse("constraint type '" + c.type + "' on " + toString(f) + "-" + toString(m) +
                " is not encoded");
}

}  // namespace

bool encodePose(const Problem& problem, int chart, PoseEncoding* out, std::string* why,
                unsigned alternative) {
  *out = PoseEncoding{};
  out->alternative = alternative;
  out->frames = detail::normalisationOf(problem);
  out->chart = kCharts[chart == 0 ? 0 : 1];
  PoseEncoder encoder(out, why, alternative);
  encoder.chart(out->chart);
  for (const int i : detail::canonicalOrder(problem)) {
    const InputConstraint& c = problem.constraints[i];
    const std::string at = "constraint " + std::to_string(i) + ": ";
    if (!detail::isEncodedType(c.type)) {
      *why = at + "constraint type '" + c.type + "' is not a built-in one";
      return false;
    }
    if (c.isRange() && c.min != c.max) {
      *why = at + "a range is not encoded";
      return false;
    }
    InputConstraint exact = c;
    if (c.isRange()) exact.has_value = true, exact.value = c.min;
    if (!encoder.add(exact, detail::normalised(problem, exact, out->frames))) {
      *why = at + *why;
      return false;
    }
  }
  const int n = static_cast<int>(out->equations.size()) - 2;
  int rotational = 0;  // equations on the rotation alone
  for (const PoseEquation& q : out->equations) rotational += q.kind == K::kDirection;
  if (n == 6 && rotational > 3) {
    *why = std::to_string(rotational) + " equations on the rotation alone (3 unknowns) and 6 - " +
           std::to_string(rotational) + " on the position: not isolated poses";
    return false;
  }
  if (n != 6) {
    *why = "the constraints give " + std::to_string(n) +
           " equations on the pose (6 unknowns): " + (n < 6 ? "a set of poses" : "overdetermined") +
           ", not isolated poses";
    return false;
  }
  return true;
}

}  // namespace relpos::complete
