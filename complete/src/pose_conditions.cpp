#include "pose_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace relpos::complete::detail {
namespace {

// An exact angle this close to 0 or π is a parallelism (its cosine would be singular there).
constexpr double kParallelAngle = 1e-9;

std::array<double, 3> arr(const Vector3d& v) { return {v[0], v[1], v[2]}; }

// Two unit vectors across d.
void across(const Vector3d& d, Vector3d* e1, Vector3d* e2) {
  const Vector3d n = d.normalized();
  const Vector3d a = std::abs(n.x()) < 0.6 ? Vector3d::UnitX() : Vector3d::UnitY();
  *e1 = n.cross(a).normalized();
  *e2 = n.cross(*e1);
}

// What the fundamentals of one alternative say, before normalisation (world and mobile frame as
// given): appended to `out`.
struct Raw {
  Condition c;
  Vector3d p, u, q, d;  // unnormalised copies of the points and directions
};

class Builder {
 public:
  explicit Builder(std::vector<Raw>* out) : out_(out) {}

  // False when f is a kind the conditions do not take (a plugin's).
  bool add(const Fundamental& f, int source) {
    const double lo = f.lo, hi = f.hi;
    switch (f.kind) {
      case FundamentalKind::kPointPoint:
        if (f.exact() && f.lo == 0.0) {
          for (int i = 0; i < 3; ++i)
            push(ConditionKind::kPointPlane, f.p, Vector3d::Zero(), f.q, Vector3d::Unit(i), 0.0,
                 0.0, source);
          return true;
        }
        push(ConditionKind::kPointPoint, f.p, Vector3d::Zero(), f.q, Vector3d::Zero(), squareLo(lo),
             squareHi(hi), source);
        return true;
      case FundamentalKind::kPointLine:
        if (f.point_side == Side::kMobile) {
          if (f.exact() && f.lo == 0.0) {
            Vector3d e1, e2;
            across(f.d, &e1, &e2);
            push(ConditionKind::kPointPlane, f.p, Vector3d::Zero(), f.q, e1, 0.0, 0.0, source);
            push(ConditionKind::kPointPlane, f.p, Vector3d::Zero(), f.q, e2, 0.0, 0.0, source);
            return true;
          }
          push(ConditionKind::kPointLine, f.p, Vector3d::Zero(), f.q, f.d, squareLo(lo),
               squareHi(hi), source);
          return true;
        }
        // the fixed point p, the mobile line (q, d)
        if (f.exact() && f.lo == 0.0) {
          Vector3d e1, e2;
          across(f.d, &e1, &e2);
          push(ConditionKind::kPlanePoint, f.q, e1, f.p, Vector3d::Zero(), 0.0, 0.0, source);
          push(ConditionKind::kPlanePoint, f.q, e2, f.p, Vector3d::Zero(), 0.0, 0.0, source);
          return true;
        }
        push(ConditionKind::kLinePoint, f.q, f.d, f.p, Vector3d::Zero(), squareLo(lo), squareHi(hi),
             source);
        return true;
      case FundamentalKind::kPointPlane:
        if (f.point_side == Side::kMobile)
          push(ConditionKind::kPointPlane, f.p, Vector3d::Zero(), f.q, f.d, lo, hi, source);
        else  // the fixed point p, the mobile plane (q, d)
          push(ConditionKind::kPlanePoint, f.q, f.d, f.p, Vector3d::Zero(), lo, hi, source);
        return true;
      case FundamentalKind::kAngle: {
        if (f.exact() && (f.lo < kParallelAngle || f.lo > kPi - kParallelAngle)) {
          // R u_m = ±u_f: two cosines 0 across u_f, and the sign as an inequality
          Vector3d e1, e2;
          across(f.q, &e1, &e2);
          push(ConditionKind::kCosine, Vector3d::Zero(), f.p, Vector3d::Zero(), e1, 0.0, 0.0,
               source);
          push(ConditionKind::kCosine, Vector3d::Zero(), f.p, Vector3d::Zero(), e2, 0.0, 0.0,
               source);
          if (f.lo < kParallelAngle)
            push(ConditionKind::kCosine, Vector3d::Zero(), f.p, Vector3d::Zero(), f.q, 0.5, kInf,
                 source);
          else
            push(ConditionKind::kCosine, Vector3d::Zero(), f.p, Vector3d::Zero(), f.q, -kInf, -0.5,
                 source);
          return true;
        }
        // angle in [lo, hi] ⇔ cos in [cos hi, cos lo]; the ends 0 and π bound nothing
        const double clo = hi >= kPi ? -kInf : std::cos(hi);
        const double chi = lo <= 0.0 ? kInf : std::cos(lo);
        push(ConditionKind::kCosine, Vector3d::Zero(), f.p, Vector3d::Zero(), f.q,
             f.exact() ? std::cos(lo) : clo, f.exact() ? std::cos(lo) : chi, source);
        return true;
      }
      case FundamentalKind::kLineLine:
        if (f.exact() && f.lo == 0.0) {
          push(ConditionKind::kSkew, f.p, f.u, f.q, f.d, 0.0, 0.0, source);
          return true;
        }
        if (f.exact()) {
          push(ConditionKind::kSkewSquared, f.p, f.u, f.q, f.d, 0.0, 0.0, source, lo * lo);
          return true;
        }
        if (lo > 0.0)
          push(ConditionKind::kSkewSquared, f.p, f.u, f.q, f.d, 0.0, kInf, source, lo * lo);
        if (std::isfinite(hi))
          push(ConditionKind::kSkewSquared, f.p, f.u, f.q, f.d, -kInf, 0.0, source, hi * hi);
        return true;
      case FundamentalKind::kCustom:
        break;
    }
    return false;
  }

 private:
  static double squareLo(double lo) { return lo <= 0.0 ? -kInf : lo * lo; }
  static double squareHi(double hi) { return std::isfinite(hi) ? hi * hi : kInf; }

  void push(ConditionKind kind, const Vector3d& p, const Vector3d& u, const Vector3d& q,
            const Vector3d& d, double lo, double hi, int source, double k = 0.0) {
    // an exact squared distance (lo == hi) stays an equation; a range with nothing to bound
    // (−∞, ∞) is dropped
    if (!(lo > -kInf) && !(hi < kInf)) return;
    Raw r;
    r.c.kind = kind;
    r.c.lo = lo;
    r.c.hi = hi;
    r.c.k = k;
    r.c.source = source;
    r.p = p, r.u = u.squaredNorm() > 0.0 ? u.normalized() : u;
    r.q = q, r.d = d.squaredNorm() > 0.0 ? d.normalized() : d;
    out_->push_back(r);
  }
  std::vector<Raw>* out_;
};

// Which lengths a kind's bounds are: 0 none (a cosine), 1 a length, 2 a squared length.
int lengthPower(ConditionKind k) {
  switch (k) {
    case ConditionKind::kPointPoint:
    case ConditionKind::kPointLine:
    case ConditionKind::kLinePoint:
    case ConditionKind::kSkewSquared:
      return 2;
    case ConditionKind::kPointPlane:
    case ConditionKind::kPlanePoint:
    case ConditionKind::kSkew:
      return 1;
    case ConditionKind::kCosine:
      return 0;
  }
  return 0;
}

bool usesPoints(ConditionKind k) { return k != ConditionKind::kCosine; }

ConditionSystem normalise(const std::vector<Raw>& raws) {
  ConditionSystem s;
  Normalisation& n = s.frame;
  Vector3d lo_w = Vector3d::Constant(kInf), hi_w = -lo_w, lo_m = lo_w, hi_m = hi_w;
  for (const Raw& r : raws) {
    if (!usesPoints(r.c.kind)) continue;
    lo_w = lo_w.cwiseMin(r.q), hi_w = hi_w.cwiseMax(r.q);
    lo_m = lo_m.cwiseMin(r.p), hi_m = hi_m.cwiseMax(r.p);
  }
  if (lo_w.x() <= hi_w.x()) n.centre_W = 0.5 * (lo_w + hi_w), n.centre_M = 0.5 * (lo_m + hi_m);
  double L = 0.0;
  for (const Raw& r : raws) {
    if (!usesPoints(r.c.kind)) continue;
    L = std::max({L, (r.q - n.centre_W).norm(), (r.p - n.centre_M).norm()});
    for (double b : {r.c.lo, r.c.hi, r.c.k})
      if (std::isfinite(b))
        L = std::max(L, lengthPower(r.c.kind) == 2 ? std::sqrt(std::abs(b)) : std::abs(b));
  }
  n.scale = L > 0.0 ? L : 1.0;
  for (const Raw& r : raws) {
    Condition c = r.c;
    if (usesPoints(c.kind)) c.p = arr(n.mobilePoint(r.p)), c.q = arr(n.fixedPoint(r.q));
    c.u = arr(r.u), c.d = arr(r.d);
    const double f = std::pow(n.scale, lengthPower(c.kind));
    c.lo /= f, c.hi /= f, c.k /= n.scale * n.scale;
    (c.equation() ? s.equations : s.inequalities).push_back(c);
  }
  return s;
}

// A canonical order of the conditions (not their constraints' order): the same problem with its
// constraints permuted gives the same systems, so the same descents and the same charts.
bool conditionBefore(const Condition& a, const Condition& b) {
  auto key = [](const Condition& c) {
    return std::make_tuple(c.kind, c.p, c.u, c.q, c.d, c.k, c.lo, c.hi);
  };
  return key(a) < key(b);
}

bool listBefore(const std::vector<Condition>& a, const std::vector<Condition>& b) {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), conditionBefore);
}

bool systemBefore(const ConditionSystem& a, const ConditionSystem& b) {
  if (listBefore(a.equations, b.equations)) return true;
  if (listBefore(b.equations, a.equations)) return false;
  return listBefore(a.inequalities, b.inequalities);
}

}  // namespace

bool buildConditionSystems(const Problem& problem, const Registry& registry,
                           std::vector<ConditionSystem>* out, std::string* why,
                           int max_alternatives) {
  // the alternatives of each constraint, then every combination
  std::vector<std::vector<std::vector<Raw>>> per;  // constraint → alternative → conditions
  int combinations = 1;
  for (std::size_t i = 0; i < problem.constraints.size(); ++i) {
    const InputConstraint& c = problem.constraints[i];
    const ConstraintType* t = registry.constraintType(c.type);
    if (!t || !t->decompose) {
      *why = "constraint " + std::to_string(i) + " ('" + c.type + "') has no decomposition";
      return false;
    }
    Decomposition d;
    t->decompose(c, c.fixed.placed(problem.fixed.pose), SourceMask{1} << (i % 64), d, t->context);
    if (d.unhandled || d.alternatives.empty()) {
      *why = "constraint " + std::to_string(i) + " ('" + c.type +
             "'): " + (d.unhandled ? d.unhandled : "no fundamental constraints");
      return false;
    }
    per.emplace_back();
    for (const auto& alt : d.alternatives) {
      std::vector<Raw> raws;
      Builder b(&raws);
      for (const Fundamental& f : alt)
        if (!b.add(f, static_cast<int>(i))) {
          *why = "constraint " + std::to_string(i) + " is a kind of a plugin's";
          return false;
        }
      per.back().push_back(std::move(raws));
    }
    combinations *= static_cast<int>(per.back().size());
    if (combinations > max_alternatives) {
      *why = "more than " + std::to_string(max_alternatives) +
             " combinations of 'either' orientations";
      return false;
    }
  }
  out->clear();
  for (int k = 0; k < combinations; ++k) {
    std::vector<Raw> raws;
    int rest = k;
    for (const auto& alts : per) {
      const auto& chosen = alts[static_cast<std::size_t>(rest) % alts.size()];
      rest /= static_cast<int>(alts.size());
      raws.insert(raws.end(), chosen.begin(), chosen.end());
    }
    ConditionSystem sys = normalise(raws);
    std::sort(sys.equations.begin(), sys.equations.end(), conditionBefore);
    std::sort(sys.inequalities.begin(), sys.inequalities.end(), conditionBefore);
    out->push_back(std::move(sys));
  }
  std::sort(out->begin(), out->end(), systemBefore);
  return true;
}

// The largest magnitude of the problem's coordinates and values as placed (the fixed frame's
// placement included), and of the mobile object's initial pose: beyond 1e100 a pose's squared
// distances overflow, as the rules' own check says (core/src/centring.cpp).
double largestMagnitude(const Problem& p) {
  double m = std::max(p.fixed.pose.translation().cwiseAbs().maxCoeff(),
                      p.mobile.pose.translation().cwiseAbs().maxCoeff());
  for (const InputConstraint& c : p.constraints) {
    const Feature f = c.fixed.placed(p.fixed.pose);
    for (const Feature* x : {&f, &c.mobile}) m = std::max(m, x->point.cwiseAbs().maxCoeff());
    for (double v : {c.value, c.min, c.max})
      if (std::isfinite(v))
        m = std::max(m, std::abs(v));
      else if (std::isnan(v))
        return v;
  }
  return m;
}

double worstViolation(const Problem& problem, const Registry& registry, const Tolerance& tol,
                      const Isometry3d& X) {
  double worst = 0.0;
  for (const InputConstraint& c : problem.constraints) {
    const ConstraintType* t = registry.constraintType(c.type);
    if (!t || !t->violation) return std::numeric_limits<double>::infinity();
    const double v =
        t->violation(c, c.fixed.placed(problem.fixed.pose), c.mobile.placed(X), tol, t->context);
    if (!(v <= worst)) worst = std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  }
  return worst;
}

double toleranceInUnits(const Condition& c, double length, double angle) {
  switch (c.kind) {
    case ConditionKind::kCosine:
      return angle * std::sqrt(std::max(0.0, 1.0 - c.lo * c.lo));
    case ConditionKind::kPointPoint:
    case ConditionKind::kPointLine:
    case ConditionKind::kLinePoint:
      return 2.0 * std::sqrt(std::max(c.lo, 0.0)) * length;
    default:
      return length;
  }
}

double toleranceAt(const Condition& c, const Matrix3d& R, double length, double angle) {
  const double allowed = toleranceInUnits(c, length, angle);
  if (c.kind != ConditionKind::kSkew && c.kind != ConditionKind::kSkewSquared) return allowed;
  const double n = 0.9 * (R * vec(c.u)).cross(vec(c.d)).norm();
  return c.kind == ConditionKind::kSkew ? n * allowed
                                        : 2.0 * std::sqrt(std::max(c.k, 0.0)) * n * n * allowed;
}

Condition inBaseFrame(const Condition& c, const Matrix3d& R0, const Vector3d& t0) {
  Condition r = c;
  const Vector3d q(c.q[0], c.q[1], c.q[2]), d(c.d[0], c.d[1], c.d[2]);
  r.q = arr(R0.transpose() * (q - t0));
  r.d = arr(R0.transpose() * d);
  return r;
}

void inBaseFrame(const std::vector<Condition>& in, const Matrix3d& R0, const Vector3d& t0,
                 std::vector<Condition>* out) {
  out->clear();
  for (const Condition& c : in) out->push_back(inBaseFrame(c, R0, t0));
}

}  // namespace relpos::complete::detail
