// PMF App. IV Table X: two angle constraints ∠(u_m, u_f) = α, ∠(v_m, v_f) = β, with
// σ_m = ∠(u_m, v_m) and σ_f = ∠(u_f, v_f). The rows handled here are those that reduce the pair
// to parallelisms (via the vectors s± of App. II) or prove it redundant or incompatible; the
// general pair is left to the two-angle rotation of App. III-D.
#include <algorithm>
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace angle_angle_family {
using namespace detail;

// App. II: unit vectors at angle a from u and b from v (u, v independent unit vectors).
// Returns how many (0, 1 or 2). `*err`: how far they may be from the exact ones when the angles
// and vectors are known to `in_err` — and never better than their own rounding (kInputRounding),
// which nearly parallel axes magnify like any other uncertainty (a first-order bound; a square
// root where the cones touch); `*gain`: how much the axes' closeness magnifies it (1 + 2 / sin of
// their angle).
int sPlusMinus(const Vector3d& u, const Vector3d& v, double a, double b, const Tolerance& tol,
               double in_err, Vector3d s[2], double* err, double* gain) {
  // In the basis (u, v_u, w): s = cos a u + c_φ v_u ± c_t w with s·v = cos b. Near parallel axes
  // every term below is taken where it keeps its digits: v's part across u and sin σ from the
  // short difference of the axes, 1 − cos σ from it too, cos b − cos a from the half-angles
  // (cos b − cos a cos σ would cancel to rounding, then be divided by sin σ).
  const double cs = u.dot(v);
  const Vector3d v_perp = perpendicularPart(v, u);
  const double ss = v_perp.norm();
  const Vector3d vu = v_perp / ss;
  const Vector3d w = u.cross(vu);
  const double one_minus_cs = cs > 0.0 ? 0.5 * (v - u).squaredNorm() : 1.0 - cs;
  const double cb_minus_ca = -2.0 * std::sin(0.5 * (a + b)) * std::sin(0.5 * (b - a));
  const double cphi = (cb_minus_ca + std::cos(a) * one_minus_cs) / ss;
  const double sa = std::sin(a);
  const double ct2 = (sa - cphi) * (sa + cphi);
  // The position across the cones' common plane (cphi) moves by e; their height above it (ct) by
  // e / ct, or by sqrt(2 e) where they barely meet.
  *gain = 1.0 + 2.0 / ss;
  const double e = (in_err + kInputRounding) * *gain;
  *err = e + std::min(e / std::sqrt(std::max(ct2, 0.0)), std::sqrt(2.0 * e));
  if (ct2 < -4 * (tol.angle + e)) return 0;
  const Vector3d base = std::cos(a) * u + cphi * vu;
  // Where the cones' overlap is within what the inputs are known to (ct2 moves by about 2 e), the
  // two meetings are one tangent direction moved apart by the inputs' error: s± = base ± sqrt(ct2)
  // would each be off the exact one by that square root (3e-6 rad for errors of 1e-11), the
  // tangent direction by no more than the inputs.
  if (ct2 <= 4 * (tol.angle * tol.angle + e)) {
    s[0] = base.normalized();
    // The exact meetings are base ± sqrt(ct2') w, ct2' within 2 e of ct2: each as far from the
    // one direction as that root (measured: meetings 3.2e-4 rad from it where the bound above
    // said 2.2e-4, and the pair was then found incompatible at a pose that meets both).
    *err = std::max(*err, e + std::sqrt(std::max(ct2, 0.0) + 2.0 * e));
    return 1;
  }
  const double ct = std::sqrt(ct2);
  s[0] = (base + ct * w).normalized();
  s[1] = (base - ct * w).normalized();
  return 2;
}

enum Case { kIncompatible, kSameVector, kTwoCones, kParallelFixes, kParallelAndAngle };

// Whether the directions s± are known well enough to replace the cones by. Where the cones' axes
// are nearly parallel, their meeting moves by far more than the inputs' uncertainty (gain: 1/sin
// of the axes' angle): even given vectors, exact but for rounding, then meet where the rounding
// puts them, 1e-9 rad off at axes 1e-7 apart. Such a pair waits (RuleOutput::defer) for the
// pairs of its set that decide better (another parallelism makes the same vector's cone meet
// one of them at a good angle); alone, it is computed in the last round as far as rounding so
// magnified stays below the angle tolerance (solver.cpp, combineInRounds), carrying its err.
// Derived inputs (err > 0) are refused in every round: a parallelism that uncertain would let
// later comparisons wave real differences through (the pair is left to the matchers). (The square
// root where the cones barely meet is no gain of rounding but the geometry's own.)
enum class Conditioning { kGood, kDefer, kRefuse };
Conditioning conditioning(double gain, double in_err, const Tolerance& given) {
  if (in_err > 0.0 && !(gain <= kConditioningBound)) return Conditioning::kRefuse;
  return given.tooIllConditioned(gain) ? Conditioning::kDefer : Conditioning::kGood;
}
// Applies a verdict of conditioning(); true when the rule may go on.
bool proceed(Conditioning c, RuleOutput& out) {
  if (c == Conditioning::kDefer) out.defer();
  return c == Conditioning::kGood;
}

struct Ang {
  Vector3d m, f;
  double a;
  SourceMask src;
  double err;
};

// Snap angles at 0 or π to a parallelism with the fixed vector flipped. The snap moves the
// constraint by up to the tolerance: that joins its uncertainty, or two parallelisms each snapped
// by the tolerance would be compared within it (and found apart by twice it).
Ang snap(const Fundamental& x, const Tolerance& given) {
  const Tolerance tol = given.widened(x.err);
  Ang r{x.p, x.q, x.value(), x.sources, x.err};
  if (tol.equalAngle(r.a, kPi)) r.f = -r.f, r.a = kPi - r.a;
  if (tol.zeroAngle(r.a)) r.err += std::abs(r.a), r.a = 0;
  return r;
}

// An angle of 0 or π (after snap() and the flips below, which turn 0 into π).
bool isParallelism(const Ang& x) { return x.a == 0 || x.a == kPi; }

// A parallelism that alone fixes the other constraint's angle at `implied`: that constraint is
// redundant, or the pair incompatible. `first_is_parallelism`: which of the pair is redundant.
void parallelismFixes(double implied, double angle, bool first_is_parallelism, const Tolerance& tol,
                      RuleOutput& out) {
  if (tol.equalAngle(implied, angle)) {
    out.fire(kParallelFixes);
    return first_is_parallelism ? out.redundantSecond() : out.redundantFirst();
  }
  return out.fire(kIncompatible)
      .incompatible(
          "a parallelism fixes the angle of the other constraint to another value (PMF App. IV "
          "Table X)");
}

void twoAngles(const Fundamental& fa, const Fundamental& fb, const Tolerance& given,
               RuleOutput& out, const void* /*context*/) {
  Ang a = snap(fa, given), b = snap(fb, given);
  // Every comparison allows for how far derived or snapped vectors may be from the exact ones.
  double in_err = a.err + b.err;
  Tolerance tol = given.widened(in_err);
  // Same mobile vector (σ_m = 0 or π): one vector at α from u_f and β from v_f.
  double sm = angleBetween(a.m, b.m);
  if (sm >= kPi - tol.angle) b.m = -b.m, b.a = kPi - b.a, sm = kPi - sm;
  if (sm <= tol.angle) {
    // Taking b's mobile vector for a's moves b by σ_m: that joins its uncertainty, as a snap to a
    // parallelism does, or two parallelisms on vectors 1e-9 apart would be compared with fixed
    // vectors 1.01e-9 apart within 1e-9 (and found different, or met by a vector between them
    // that is neither).
    b.m = a.m, b.err += sm, in_err += sm;
    tol = given.widened(in_err);
    double sf = angleBetween(a.f, b.f);
    if (sf >= kPi - tol.angle) b.f = -b.f, b.a = kPi - b.a, sf = kPi - sf;
    if (sf <= tol.angle) {
      // Likewise a's fixed vector taken for b's: a direction at α from one and β from the other,
      // σ_f apart, exists wherever |α − β| ≤ σ_f (the angles 1e-9 apart from fixed vectors 1e-9
      // apart were found incompatible, a pose meeting both to 1e-15 notwithstanding).
      b.err += sf, in_err += sf;
      tol = given.widened(in_err);
      // Keep the one known best: the solution then meets the other within its uncertainty.
      if (tol.equalAngle(a.a, b.a)) {
        out.fire(kSameVector);
        return a.err > b.err ? out.redundantFirst() : out.redundantSecond();
      }
      return out.fire(kIncompatible)
          .incompatible(
              "one direction at two different angles from the same direction (PMF App. IV Table "
              "X)");
    }
    // A parallelism gives the direction itself, which makes the other angle or not. (As a cone
    // of half-angle 0 it would meet the other cone only by the tolerance on a square, ~1e-5 rad:
    // a direction that keeps neither.)
    if (isParallelism(a) || isParallelism(b)) {
      const bool pa = isParallelism(a);
      const Ang& par = pa ? a : b;
      const Ang& other = pa ? b : a;
      const Vector3d dir = par.a == 0 ? par.f : Vector3d(-par.f);
      return parallelismFixes(angleBetween(dir, other.f), other.a, pa, tol, out);
    }
    Vector3d s[2];
    double err = 0.0, gain = 1.0;
    const int n = sPlusMinus(a.f, b.f, a.a, b.a, given, in_err, s, &err, &gain);
    if (n == 0)
      return out.fire(kIncompatible)
          .incompatible("no direction makes both angles (PMF App. IV Table X, row 1)");
    if (!proceed(conditioning(gain, in_err, given), out)) return;
    out.fire(kTwoCones);
    for (int k = 0; k < n; ++k) one(out, withErr(Fundamental::angle(a.m, s[k], 0.0, 0), err));
    return;
  }
  const bool pa = a.a == 0, pb = b.a == 0;
  if (pa && pb) {
    // Two parallelisms: the mobile and fixed vectors must form the same angle (rigid rotation).
    if (!tol.equalAngle(sm, angleBetween(a.f, b.f)))
      return out.fire(kIncompatible)
          .incompatible(
              "two parallelisms whose mobile vectors and fixed vectors form different angles (PMF "
              "App. IV Table X, row 1)");
    return;  // Table III row 1 solves it
  }
  if (!pa && !pb) return;  // App. III-D two-angle rotation
  // One parallelism (u_m ∥ u_f) and one angle β on v: R v_m lies at σ_m from u_f and β from v_f
  // (Table X, row with β = 0): v_m ∥ s±(u_f, v_f, σ_m, β).
  const Ang& par = pa ? a : b;
  const Ang& ang = pa ? b : a;
  const double sf = angleBetween(par.f, ang.f);
  if (sf <= tol.angle || sf >= kPi - tol.angle) {
    // v_f ∥ ±u_f: the angle is fixed by the parallelism alone — to within the angle between them,
    // which joins the uncertainty as above.
    const double off = std::min(sf, kPi - sf);
    return parallelismFixes(sf <= tol.angle ? sm : kPi - sm, ang.a, pa, given.widened(in_err + off),
                            out);
  }
  Vector3d s[2];
  double err = 0.0, gain = 1.0;
  const int n = sPlusMinus(par.f, ang.f, sm, ang.a, given, in_err, s, &err, &gain);
  if (n == 0)
    return out.fire(kIncompatible)
        .incompatible(
            "a parallelism and an angle that no rotation satisfies together (PMF App. IV Table X, "
            "row 1)");
  if (!proceed(conditioning(gain, in_err, given), out)) return;
  out.fire(kParallelAndAngle);
  for (int k = 0; k < n; ++k) {
    Alt& alt = out.addAlternative();
    alt.push_back(withErr(Fundamental::angle(par.m, par.f, 0.0, 0), par.err));
    alt.push_back(withErr(Fundamental::angle(ang.m, s[k], 0.0, 0), err));
  }
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table X, row 1"},
    {kSameVector, "same-vector", "PMF App. IV Table X, row 2 (σ_a = σ_b = nπ, α = β)"},
    {kTwoCones, "two-cones", "PMF App. IV Table X, row 7 (σ_a = 0): s± of App. II"},
    {kParallelFixes, "parallel-fixes-angle", "PMF App. IV Table X (β = 0, σ_b = nπ)"},
    {kParallelAndAngle, "parallel-and-angle", "PMF App. IV Table X, row 8 (β = 0): s± of App. II"}};

}  // namespace angle_angle_family

constexpr RuleFamily families::angle_angle =
    family("angle+angle", "PMF App. IV Table X", FundamentalKind::kAngle, FundamentalKind::kAngle,
           &angle_angle_family::twoAngles, angle_angle_family::kCases);

}  // namespace relpos::rules
