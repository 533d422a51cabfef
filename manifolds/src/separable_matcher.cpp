// The separable matcher (PMF §V, Algorithm 1): matches the combined rotational set to a row of
// Table III and the combined translational set to a row of Table IV, and emits one branch per
// rotational solution.
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "derived_sets.hpp"
#include "relpos/core/branch_sink.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/manifolds/builtin.hpp"
#include "relpos/manifolds/catalogue.hpp"
#include "relpos/manifolds/revolved.hpp"
#include "relpos/manifolds/separable.hpp"

namespace relpos::manifolds {
namespace {

using detail::kMaxRotations;
using detail::RotationAlternatives;

// An angle constraint with its value snapped to a parallelism when it is 0 or π.
struct Angle {
  Vector3d u_m, u_f;
  double alpha;
  bool parallel;
  SourceMask sources;
  double err;  // Fundamental::err: how far the vectors or the angle may be from the exact ones
};

Angle normalise(const Fundamental& f, const Tolerance& given) {
  const Tolerance tol = given.widened(f.err);
  Angle a{f.p, f.q, f.value(), false, f.sources, f.err};
  // A snap moves the constraint by up to the tolerance: that joins its uncertainty.
  if (tol.zeroAngle(a.alpha)) {
    a.parallel = true;
    a.err += std::abs(a.alpha);
    a.alpha = 0;
  } else if (tol.equalAngle(a.alpha, kPi)) {
    a.parallel = true;
    a.err += std::abs(kPi - a.alpha);
    a.alpha = 0;
    a.u_f = -a.u_f;
  }
  return a;
}

MatchResult inconsistent(MatchContext& ctx, SourceMask m, const char* why) {
  ctx.conflict = m;
  ctx.reason = why;
  return MatchResult::kInconsistent;
}

// Two parallelisms on independent vectors: one rotation (App. III-A), if the angle between the
// mobile vectors equals the angle between the fixed ones (within what their derivation leaves
// uncertain). The rotation meets the better known one exactly and leaves the mismatch to the
// other: a parallelism derived from a short span can turn by far more than one from a long span
// before a point moves by the length tolerance.
// Whether two parallelisms on mobile vectors whose cross product has norm `s` fix the rotation
// well enough to build on. The turn about the first vector is read off the second's part across
// it, so it is known only to (the vectors' uncertainty and rounding) / s: at s = 1e-7 rounding
// alone turns it by 3e-8 rad, and every point a unit away by 30 length tolerances, enough to call
// a feasible problem inconsistent once the rotation is taken as known. Beyond the gain the rules
// accept (kConditioningBound) the pair is left alone, and the set unhandled unless another pair or
// matcher decides it.
bool fixesRotationWell(double s) { return 1.0 <= s * kConditioningBound; }

MatchResult twoParallels(MatchContext& ctx, const Angle& a0, const Angle& b0,
                         RotationAlternatives& out) {
  const Tolerance tol = ctx.tol.widened(a0.err + b0.err);
  const double s = a0.u_m.cross(b0.u_m).norm();
  if (s <= tol.angle || !fixesRotationWell(s)) return MatchResult::kNoMatch;
  if (!tol.equalAngle(angleBetween(a0.u_m, b0.u_m), angleBetween(a0.u_f, b0.u_f)))
    return inconsistent(ctx, a0.sources | b0.sources,
                        "two parallelisms whose mobile and fixed vectors form different angles");
  const bool swap = b0.err < a0.err;
  const Angle& a = swap ? b0 : a0;
  const Angle& b = swap ? a0 : b0;
  // Meeting a exactly, the rotation is off by a's own uncertainty, and turned about it by what
  // both leave uncertain in b's part across a (of length s).
  out.add(rotation::Fixed(rotationPairs(a.u_m, b.u_m, a.u_f, b.u_f)), a.err + (a.err + b.err) / s);
  return MatchResult::kMatched;
}

// Two angles (App. III-D): R(φ) = R(u_f, φ) R0 R(u_m, θ(φ)), φ restricted to where the second
// angle can be met: w(φ)·v_f ∈ [cos(σ_m + β), cos(σ_m − β)] with w(φ) = R(u_f, φ) R0 u_m.
struct PhiIntervals {
  struct Interval {
    double lo, hi;
    bool periodic;
  } iv[2];
  int count = 0;  // 0: no rotation satisfies both angles
  bool degenerate = false;
};

// The φ where h0 + amp cos(φ − φ0) lies in [lo, hi] (amp > 0): none, one arc, two arcs
// symmetric about φ0, or the whole turn. The cosines are known to about the angle tolerance:
// just beyond ±1, the band touches the sinusoid.
PhiIntervals bandIntervals(double h0, double amp, double phi0, double lo, double hi,
                           const Tolerance& tol) {
  PhiIntervals out;
  const double L = (lo - h0) / amp;
  const double U = (hi - h0) / amp;
  const double eps = tol.angle / amp;
  if (L > 1.0 + eps || U < -1.0 - eps) return out;
  double psi_in = std::acos(clampUnit(U));   // |φ − φ0| >= psi_in
  double psi_out = std::acos(clampUnit(L));  // |φ − φ0| <= psi_out
  // The band's edge at the sinusoid's top (bottom) within the tolerance, measured as angles (the
  // values are cosines): the arc excluded about it holds only poses within tol.angle of the range,
  // and its width, the square root of the cosines' rounding, would split one arc in two (measured:
  // an angle range [0, 45°] about a spin axis across it, 4e-8 rad apart in a world moved 1e6).
  if (std::abs(h0) + amp <= 1.0 + 1e-12) {
    if (std::acos(clampUnit(hi)) - std::acos(clampUnit(h0 + amp)) <= tol.angle) psi_in = 0.0;
    if (std::acos(clampUnit(h0 - amp)) - std::acos(clampUnit(lo)) <= tol.angle) psi_out = kPi;
  }
  if (psi_in <= tol.angle && psi_out >= kPi - tol.angle) {
    out.iv[out.count++] = {-kPi, kPi, true};
  } else if (psi_in <= tol.angle) {
    out.iv[out.count++] = {phi0 - psi_out, phi0 + psi_out, false};
  } else if (psi_out >= kPi - tol.angle) {
    out.iv[out.count++] = {phi0 + psi_in, phi0 + 2 * kPi - psi_in, false};
  } else {
    out.iv[out.count++] = {phi0 + psi_in, phi0 + psi_out, false};
    out.iv[out.count++] = {phi0 - psi_out, phi0 - psi_in, false};
  }
  return out;
}

// A spun vector w(φ) = R(u_f, φ) w0 against a fixed v_f: w(φ)·v_f = h0 + amp cos(φ − φ0).
struct Sinusoid {
  double h0, amp, phi0;
};
Sinusoid spunDot(const Vector3d& u_f, const Vector3d& w0, const Vector3d& v_f) {
  const Vector3d w0_perp = w0 - w0.dot(u_f) * u_f;
  const Vector3d vf_perp = v_f - v_f.dot(u_f) * u_f;
  // φ0: the φ at which w(φ) leans furthest toward v_f.
  return {w0.dot(u_f) * v_f.dot(u_f), w0_perp.norm() * vf_perp.norm(),
          std::atan2(w0_perp.cross(vf_perp).dot(u_f), w0_perp.dot(vf_perp))};
}

PhiIntervals twoAngleIntervals(const Angle& a, const Angle& b, const rotation::TwoAngle& base,
                               const Tolerance& tol) {
  PhiIntervals out;
  const double sigma_m = angleBetween(a.u_m, b.u_m);
  const Vector3d vf_perp = b.u_f - b.u_f.dot(a.u_f) * a.u_f;
  if (std::sin(sigma_m) <= tol.angle || vf_perp.norm() <= tol.angle) {
    out.degenerate = true;
    return out;
  }
  const Sinusoid s = spunDot(a.u_f, base.R0 * a.u_m, b.u_f);
  return bandIntervals(std::cos(a.alpha) * a.u_f.dot(b.u_f), s.amp, s.phi0,
                       std::cos(sigma_m + b.alpha), std::cos(sigma_m - b.alpha), tol);
}

rotation::TwoAngle twoAngleBase(const Angle& a, const Angle& b) {
  return rotation::TwoAngle(rotation::OneAngle(a.u_m, a.u_f, a.alpha), b.u_m, b.u_f,
                            std::cos(b.alpha));
}

MatchResult twoAngles(MatchContext& ctx, const Angle& a0, const Angle& b0,
                      RotationAlternatives& out) {
  const Tolerance tol = ctx.tol.widened(a0.err + b0.err);
  // Either constraint can carry the free spin φ; take the one that splits the set into fewer
  // pieces (a full turn of φ gives each connected loop as one branch).
  const Angle* a = &a0;
  const Angle* b = &b0;
  rotation::TwoAngle base = twoAngleBase(*a, *b);
  PhiIntervals iv = twoAngleIntervals(*a, *b, base, tol);
  rotation::TwoAngle base2 = twoAngleBase(b0, a0);
  PhiIntervals iv2 = twoAngleIntervals(b0, a0, base2, tol);
  if (iv.degenerate || (!iv2.degenerate && iv2.count < iv.count)) {
    std::swap(a, b);
    base = base2;
    iv = iv2;
  }
  if (iv.degenerate) return MatchResult::kNoMatch;
  // Where the cone of R u_m passes through ±v_f and cos β = ±cos σ_m, the second angle holds for
  // every spin about u_m: the whole circle {R u_m = ±v_f} belongs to the set, and θ(φ) (0/0 there)
  // misses it. Add it as a one-parallelism branch.
  const double cos_sm = a->u_m.dot(b->u_m);
  int n_circles = 0;
  for (double s : {1.0, -1.0}) {
    if (tol.equalAngle(angleBetween(s * b->u_f, a->u_f), a->alpha) &&
        std::abs(s * cos_sm - std::cos(b->alpha)) <= tol.angle) {
      out.add(rotation::OneParallel(a->u_m, s * b->u_f), a->err + b->err);
      ++n_circles;
    }
  }
  if (iv.count == 0 && n_circles == 0)
    return inconsistent(ctx, a->sources | b->sources,
                        "two angle constraints that no rotation satisfies together");
  for (int k = 0; k < iv.count; ++k) {
    if (iv.iv[k].hi - iv.iv[k].lo <= tol.angle) {
      // A single φ: both θ signs meet, one discrete rotation.
      double th[1] = {0.5 * (iv.iv[k].lo + iv.iv[k].hi)};
      out.add(rotation::Fixed(base.rotation(th)), a->err + b->err);
      continue;
    }
    for (double sign : {1.0, -1.0}) {
      rotation::TwoAngle r = base;
      r.sign = sign;
      r.phi_lo = iv.iv[k].lo;
      r.phi_hi = iv.iv[k].hi;
      r.phi_periodic = iv.iv[k].periodic;
      out.add(r);
    }
  }
  return MatchResult::kMatched;
}

// Three angles on right trihedra (App. III-C): R = F R2 Mᵀ with R2 = Rx(θ1) Rz(α) Rx(θ2),
// cos(θ1 + θ2) = (cβ + cγ)/(1 + cα), cos(θ1 − θ2) = (cγ − cβ)/(1 − cα): up to 8 rotations.
MatchResult threeAngles(MatchContext& ctx, Angle a, Angle b, Angle c, RotationAlternatives& out) {
  const double tol = ctx.tol.widened(a.err + b.err + c.err).angle;
  auto ortho = [&](const Vector3d& x, const Vector3d& y) { return std::abs(x.dot(y)) <= tol; };
  if (!ortho(a.u_m, b.u_m) || !ortho(a.u_m, c.u_m) || !ortho(b.u_m, c.u_m) ||
      !ortho(a.u_f, b.u_f) || !ortho(a.u_f, c.u_f) || !ortho(b.u_f, c.u_f))
    return MatchResult::kNoMatch;
  // Make both trihedra right-handed by flipping the third vector (angle γ -> π − γ).
  if (a.u_m.cross(b.u_m).dot(c.u_m) < 0) c.u_m = -c.u_m, c.alpha = kPi - c.alpha;
  if (a.u_f.cross(b.u_f).dot(c.u_f) < 0) c.u_f = -c.u_f, c.alpha = kPi - c.alpha;
  // Put a non-degenerate angle first (cyclic order keeps the handedness).
  Angle ang[3] = {a, b, c};
  int first = 0;
  // (An angle within the tolerance of 0 or π was snapped to 0 by normalise; below the rounding
  // floor 1 − cos α is lost, and the formula below divides by it.)
  const double degenerate = ctx.tol.angleAboveRounding();
  while (first < 3 && std::sin(ang[first].alpha) < degenerate) ++first;
  Matrix3d M, F;
  const SourceMask all = a.sources | b.sources | c.sources;
  if (first == 3) {
    // Every angle is 0 or π: R2 is diagonal ±1 and must be a rotation.
    Vector3d diag(std::cos(a.alpha), std::cos(b.alpha), std::cos(c.alpha));
    diag = diag.array().round();
    if (diag.prod() < 0)
      return inconsistent(ctx, all, "three angle constraints that no rotation satisfies");
    for (int k = 0; k < 3; ++k) M.col(k) = ang[k].u_m, F.col(k) = ang[k].u_f;
    out.add(rotation::Fixed(F * diag.asDiagonal() * M.transpose()), a.err + b.err + c.err);
    return MatchResult::kMatched;
  }
  const Angle& A = ang[first];
  const Angle& B = ang[(first + 1) % 3];
  const Angle& C = ang[(first + 2) % 3];
  M.col(0) = A.u_m, M.col(1) = B.u_m, M.col(2) = C.u_m;
  F.col(0) = A.u_f, F.col(1) = B.u_f, F.col(2) = C.u_f;
  const double ca = std::cos(A.alpha), cb = std::cos(B.alpha), cc = std::cos(C.alpha);
  const double cp = (cb + cc) / (1 + ca), cm = (cc - cb) / (1 - ca);
  if (std::abs(cp) > 1 + tol || std::abs(cm) > 1 + tol)
    return inconsistent(ctx, all, "three angle constraints that no rotation satisfies");
  const double a1 = std::acos(clampUnit(cp)), a2 = std::acos(clampUnit(cm));
  for (int k = 0; k < 2; ++k)
    for (double s1 : {1.0, -1.0})
      for (double s2 : {1.0, -1.0}) {
        double psi1 = s1 * a1 + 2 * kPi * k, psi2 = s2 * a2;
        double t1 = 0.5 * (psi1 + psi2), t2 = 0.5 * (psi1 - psi2);
        Matrix3d R2 = axisAngle(Vector3d::UnitX(), t1) * axisAngle(Vector3d::UnitZ(), A.alpha) *
                      axisAngle(Vector3d::UnitX(), t2);
        Matrix3d R = F * R2 * M.transpose();
        bool dup = false;
        for (int j = 0; j < out.size(); ++j)
          dup = dup || (out.parts[j].baseRotation() - R).cwiseAbs().maxCoeff() < degenerate;
        if (!dup) out.add(rotation::Fixed(R), a.err + b.err + c.err);
      }
  return MatchResult::kMatched;
}

// Two parallelisms on independent vectors fix the rotation (App. III-A); every other rotational
// constraint then either holds (implied) or proves the set inconsistent. The pair is the one that
// fixes it best: the rotation about the first vector is read off the second's part across it,
// known to (their uncertainties + rounding) / sin of their angle, so two parallelisms on nearly
// parallel vectors fix it poorly however exact they are. The others are checked against it within
// that and their own uncertainty.
MatchResult determinedRotation(MatchContext& ctx, const Angle* ang, int n,
                               RotationAlternatives& out) {
  int best_i = -1, best_j = -1;
  double best_u = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    if (!ang[i].parallel) continue;
    for (int j = i + 1; j < n; ++j) {
      if (!ang[j].parallel) continue;
      const double s = ang[i].u_m.cross(ang[j].u_m).norm();
      if (s <= ctx.tol.widened(ang[i].err + ang[j].err).angle || !fixesRotationWell(s)) continue;
      const double u = std::min(ang[i].err, ang[j].err) +
                       (ang[i].err + ang[j].err + ctx.tol.angle + kInputRounding) / s;
      if (u < best_u) best_u = u, best_i = i, best_j = j;  // (ties: the first, deterministic)
    }
  }
  if (best_i < 0) return MatchResult::kNoMatch;
  const Angle& a = ang[best_i];
  const Angle& b = ang[best_j];
  RotationAlternatives two;
  MatchResult r = twoParallels(ctx, a, b, two);
  if (r != MatchResult::kMatched) return r;
  const Matrix3d R = two.parts[0].baseRotation();
  // What R leaves of the others (each within its tolerance) turns the features as an uncertainty
  // of R would: it joins R's.
  double mismatch = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k == best_i || k == best_j) continue;
    const Tolerance tol = ctx.tol.widened(best_u + ang[k].err);
    const double off = std::abs(angleBetween(R * ang[k].u_m, ang[k].u_f) - ang[k].alpha);
    if (!(off <= tol.angle))
      return inconsistent(ctx, a.sources | b.sources | ang[k].sources,
                          "a rotation fixed by two parallelisms violates another rotational "
                          "constraint");
    mismatch = std::max(mismatch, off);
  }
  out.add(two.parts[0], two.err[0] + mismatch);
  return MatchResult::kMatched;
}

// A parallelism (R u_m = u_f: the spin φ about u_f free) and an angle range on another mobile
// vector v_m (issue 16: a keyway within ±10°, jaws level within ±20°): φ on the arcs where
// angle(R(φ) v_m, v_f) ∈ [lo, hi], one branch each; a spin that does not move the angle (v_m
// along u_m, or v_f along u_f) keeps the whole turn or none.
MatchResult spinWithinRange(MatchContext& ctx, const Angle& par, const Fundamental& range,
                            RotationAlternatives& out) {
  const Tolerance tol = ctx.tol.widened(par.err + range.err);
  const rotation::OneParallel base(par.u_m, par.u_f);
  const Sinusoid s = spunDot(par.u_f, base.R0 * range.p, range.q);
  const double lo = std::cos(range.hi), hi = std::cos(range.lo);  // w(φ)·v_f's band
  const SourceMask both = par.sources | range.sources;
  if (s.amp <= tol.angle) {
    if (s.h0 < lo - tol.angle || s.h0 > hi + tol.angle)
      return inconsistent(ctx, both, "a parallelism that keeps another vector out of its range");
    out.add(base, par.err);
    return MatchResult::kMatched;
  }
  const PhiIntervals iv = bandIntervals(s.h0, s.amp, s.phi0, lo, hi, tol);
  if (iv.count == 0)
    return inconsistent(ctx, both, "a spin about a parallelism that never meets an angle range");
  for (int k = 0; k < iv.count; ++k) {
    const PhiIntervals::Interval& i = iv.iv[k];
    if (i.periodic) {
      out.add(base, par.err);
    } else if (i.hi - i.lo <= tol.angle) {  // the range touched at one spin
      const double phi[1] = {0.5 * (i.lo + i.hi)};
      out.add(rotation::Fixed(base.rotation(phi)), par.err + range.err);
    } else {
      rotation::OneParallel r = base;
      r.phi_lo = i.lo;
      r.phi_hi = i.hi;
      r.phi_periodic = false;
      out.add(r, par.err);
    }
  }
  return MatchResult::kMatched;
}

// Two angle constraints on one mobile vector m, at least one a range (issue 16: a torch's work
// and travel angles, a camera's viewing angles; an exact angle and a range): m's direction in the
// intersection of two bands on the sphere, the spin about m free. About one axis the bands are
// one range; otherwise a TwoAngleRange branch for each side of the plane of the fixed directions.
MatchResult oneVectorTwoRanges(MatchContext& ctx, Fundamental f, Fundamental g,
                               RotationAlternatives& out) {
  if (g.p.dot(f.p) < 0.0) {  // the angle of −m is π minus m's
    g.p = -g.p;
    const double lo = g.lo;
    g.lo = kPi - g.hi;
    g.hi = kPi - lo;
  }
  if (g.exact() && !f.exact()) std::swap(f, g);  // an exact angle is α: 2 DOF
  const Tolerance tol = ctx.tol.widened(f.err + g.err);
  const SourceMask both = f.sources | g.sources;
  const double err = f.err + g.err;
  const double sigma = angleBetween(f.q, g.q);
  if (sigma <= tol.angle || sigma >= kPi - tol.angle) {  // bands about one axis: one range
    const double g_lo = sigma <= tol.angle ? g.lo : kPi - g.hi;
    const double g_hi = sigma <= tol.angle ? g.hi : kPi - g.lo;
    const double lo = std::max(f.lo, g_lo), hi = std::min(f.hi, g_hi);
    if (lo > hi + tol.angle)
      return inconsistent(ctx, both, "two angle ranges about one axis that do not overlap");
    out.add(rotation::OneAngleRange(f.p, f.q, lo, std::max(lo, hi)), err);
    return MatchResult::kMatched;
  }
  int added = 0;
  for (double side : {1.0, -1.0}) {
    rotation::TwoAngleRange r(f.p, f.q, f.lo, f.hi, g.q, g.lo, g.hi, side);
    // Ranges that only touch (within the tolerance) keep the sliver where they touch.
    if (r.empty())
      r = rotation::TwoAngleRange(f.p, f.q, f.lo - tol.angle, f.hi + tol.angle, g.q,
                                  g.lo - tol.angle, g.hi + tol.angle, side);
    if (r.empty()) continue;
    out.add(r, err);
    ++added;
  }
  if (added == 0)
    return inconsistent(ctx, both, "two angle constraints on one vector that no direction meets");
  return MatchResult::kMatched;
}

// An exact angle (not a parallelism) and a range on another mobile vector: R = R(u_f, φ) R0
// R(u_m, θ) with θ on the arcs where the range holds, φ where they exist. The angle γ(φ) of the
// cone's direction R u_m from v_f decides: the range [lo, hi] is reachable by a spin about it
// iff |γ − σ_m| ≤ hi and min(γ + σ_m, 2π − γ − σ_m) ≥ lo, σ_m = angle(u_m, v_m) — a band of cos γ,
// which is a sinusoid in φ.
MatchResult angleWithRange(MatchContext& ctx, const Angle& a, const Fundamental& range,
                           RotationAlternatives& out) {
  const Tolerance tol = ctx.tol.widened(a.err + range.err);
  const rotation::OneAngle cone(a.u_m, a.u_f, a.alpha);
  const double sigma_m = angleBetween(a.u_m, range.p);
  const double gamma_lo = std::max({0.0, sigma_m - range.hi, range.lo - sigma_m});
  const double gamma_hi = std::min({kPi, sigma_m + range.hi, 2.0 * kPi - sigma_m - range.lo});
  const SourceMask both = a.sources | range.sources;
  const char* why = "an angle and an angle range on another vector that no rotation meets together";
  if (gamma_lo > gamma_hi + tol.angle) return inconsistent(ctx, both, why);
  const Sinusoid s = spunDot(a.u_f, cone.R0 * a.u_m, range.q);
  const double lo = std::cos(gamma_hi), hi = std::cos(gamma_lo);
  PhiIntervals iv;
  if (s.amp <= tol.angle) {  // γ the same for every φ
    if (s.h0 < lo - tol.angle || s.h0 > hi + tol.angle) return inconsistent(ctx, both, why);
    iv.iv[iv.count++] = {-kPi, kPi, true};
  } else {
    iv = bandIntervals(s.h0, s.amp, s.phi0, lo, hi, tol);
  }
  if (iv.count == 0) return inconsistent(ctx, both, why);
  for (int k = 0; k < iv.count; ++k)
    for (double sign : {1.0, -1.0}) {
      rotation::AngleWithRange r(a.u_m, a.u_f, a.alpha, range.p, range.q, range.lo, range.hi);
      r.sign = sign;
      r.phi_lo = iv.iv[k].lo;
      r.phi_hi = iv.iv[k].hi;
      r.phi_periodic = iv.iv[k].periodic;
      out.add(r, a.err + range.err);
    }
  return MatchResult::kMatched;
}

// Angle constraints with a range (issue 16): one alone, a parallelism and a range, two on one
// mobile vector, or an exact angle and a range on another; other combinations are left to
// other matchers (and then the numeric stage).
MatchResult matchRanged(MatchContext& ctx, RotationAlternatives& out) {
  const auto& rs = ctx.set.rotational;
  if (rs.size() == 1) {
    out.add(rotation::OneAngleRange(rs[0].p, rs[0].q, rs[0].lo, rs[0].hi));
    return MatchResult::kMatched;
  }
  if (rs.size() != 2) return MatchResult::kNoMatch;
  // The exact one first, else a fixed order of the geometry (not the user's).
  Fundamental f = rs[0], g = rs[1];
  auto before = [](const Fundamental& a, const Fundamental& b) {
    if (a.exact() != b.exact()) return a.exact();
    if (a.lo != b.lo) return a.lo < b.lo;
    if (a.hi != b.hi) return a.hi < b.hi;
    for (int k = 0; k < 3; ++k) {
      if (a.q[k] != b.q[k]) return a.q[k] < b.q[k];
      if (a.p[k] != b.p[k]) return a.p[k] < b.p[k];
    }
    return false;
  };
  if (before(g, f)) std::swap(f, g);
  if (f.exact()) {
    const Angle a = normalise(f, ctx.tol);
    if (a.parallel) return spinWithinRange(ctx, a, g, out);
  }
  if (f.p.cross(g.p).norm() <= ctx.tol.widened(f.err + g.err).angle)
    return oneVectorTwoRanges(ctx, f, g, out);
  if (f.exact()) return angleWithRange(ctx, normalise(f, ctx.tol), g, out);
  return MatchResult::kNoMatch;
}

// A total order on angle constraints by their geometry alone, so that the branches do not depend
// on the order in which the user listed the constraints.
bool geometricLess(const Angle& a, const Angle& b) {
  if (a.alpha != b.alpha) return a.alpha < b.alpha;
  for (int k = 0; k < 3; ++k) {
    if (a.u_f[k] != b.u_f[k]) return a.u_f[k] < b.u_f[k];
    if (a.u_m[k] != b.u_m[k]) return a.u_m[k] < b.u_m[k];
  }
  return false;
}

MatchResult matchRotation(MatchContext& ctx, RotationAlternatives& out) {
  const auto& rs = ctx.set.rotational;
  Angle ang[kMaxFundamentals];
  int n = 0, n_par = 0;
  for (const auto& f : rs) {
    ang[n] = normalise(f, ctx.tol);
    n_par += ang[n].parallel;
    ++n;
  }
  std::sort(ang, ang + n, geometricLess);
  if (n == 0) {
    out.add(rotation::Free{});
    return MatchResult::kMatched;
  }
  for (const auto& f : rs)
    if (!f.exact()) return matchRanged(ctx, out);
  if (n == 1) {
    if (ang[0].parallel)
      out.add(rotation::OneParallel(ang[0].u_m, ang[0].u_f), ang[0].err);
    else
      out.add(rotation::OneAngle(ang[0].u_m, ang[0].u_f, ang[0].alpha), ang[0].err);
    return MatchResult::kMatched;
  }
  if (n == 2 && n_par == 2) return twoParallels(ctx, ang[0], ang[1], out);
  if (n == 2 && n_par == 0) return twoAngles(ctx, ang[0], ang[1], out);
  if (n_par >= 2) return determinedRotation(ctx, ang, n, out);
  if (n == 3) return threeAngles(ctx, ang[0], ang[1], ang[2], out);
  return MatchResult::kNoMatch;
}

// The world direction of a translational constraint's element under rotation part r, when it is
// the same for every rotation of r: fixed elements always; mobile ones under a fixed rotation or
// when they lie along the spin axis of a one-parallelism rotation.
bool invariantDirection(const Fundamental& f, const RotationPart& r, const Tolerance& tol,
                        Vector3d* d_W) {
  if (f.point_side == Side::kMobile) {
    *d_W = f.d;
    return true;
  }
  const auto* spin = r.as<rotation::OneParallel>();
  if (r.is<rotation::Fixed>() || (spin && f.d.cross(spin->u_m).norm() <= tol.angle)) {
    *d_W = r.baseRotation() * f.d;
    return true;
  }
  return false;
}

// Two elements keep their relative orientation for every rotation of every alternative: both
// turn with R (same frame), or both directions are invariant. `test` must hold for the pair of
// directions (in a common frame) in each case.
template <typename Test>
bool holdsForEveryRotation(const Fundamental& a, const Fundamental& b,
                           const RotationAlternatives& rots, const Tolerance& tol, Test test) {
  if (a.point_side == b.point_side) return test(a.d, b.d);
  for (int k = 0; k < rots.size(); ++k) {
    Vector3d da, db;
    if (!invariantDirection(a, rots.parts[k], tol, &da) ||
        !invariantDirection(b, rots.parts[k], tol, &db) || !test(da, db))
      return false;
  }
  return true;
}

bool matchTranslation(const ConstraintSet& set, const Tolerance& tol,
                      const RotationAlternatives& rots, TranslationPart& out) {
  const auto& ts = set.translational;
  if (ts.size() == 0) {
    out = translation::Free{};
    return true;
  }
  if (ts.size() == 1) {
    // One shape (PMF Table V), or with a range its thick version (Somani Table VI).
    const Fundamental& f = ts[0];
    const bool ranged = !f.exact(), zero = f.value() == 0.0;
    switch (f.kind) {
      case FundamentalKind::kPointPoint:
        out = ranged ? TranslationPart(translation::Shell(f))
                     : (zero ? TranslationPart(translation::Point(f))
                             : TranslationPart(translation::Sphere(f)));
        return true;
      case FundamentalKind::kPointLine:
        out = ranged ? TranslationPart(translation::ThickCylinder(f))
                     : (zero ? TranslationPart(translation::Line(f))
                             : TranslationPart(translation::Cylinder(f)));
        return true;
      case FundamentalKind::kPointPlane:
        out =
            ranged ? TranslationPart(translation::Slab(f)) : TranslationPart(translation::Plane(f));
        return true;
      case FundamentalKind::kAngle:
      case FundamentalKind::kLineLine:
      case FundamentalKind::kCustom:
        return false;
    }
  }
  if (ts.size() != 2 || !ts[0].exact() || !ts[1].exact()) return false;
  const Fundamental* plane = nullptr;
  const Fundamental* other = nullptr;
  for (int k = 0; k < 2; ++k) {
    if (ts[k].kind == FundamentalKind::kPointPlane && !plane)
      plane = &ts[k];
    else
      other = &ts[k];
  }
  if (!plane || !other) return false;
  switch (other->kind) {
    case FundamentalKind::kPointPlane:
      out = translation::LineOfPlanes(*other, *plane);
      return holdsForEveryRotation(
          *other, *plane, rots, tol, [&](const Vector3d& a, const Vector3d& b) {
            return a.cross(b).norm() > tol.angle;  // the planes meet in a line
          });
    case FundamentalKind::kPointLine:
      out = other->value() == 0.0 ? TranslationPart(translation::PointOfLinePlane(*other, *plane))
                                  : TranslationPart(translation::Ellipse(*other, *plane));
      return holdsForEveryRotation(
          *other, *plane, rots, tol, [&](const Vector3d& a, const Vector3d& b) {
            return std::abs(a.dot(b)) > tol.angle;  // the line (axis) crosses the plane
          });
    default:
      return false;
  }
}

// Point-plane constraints (exact or ranged), points on lines and pinned points are all planes in
// translation space: up to three with independent normals, whose relative orientation no rotation
// of the set changes, make a kPlanes part (segment, strip, parallelepiped, ...).
// `given`: the problem's tolerance, before widening by the rotation's uncertainty (tol): the
// normals' independence is read off the constraints as given.
bool matchPlanes(const ConstraintSet& set, const Tolerance& tol, const Tolerance& given,
                 const RotationAlternatives& rots, TranslationPart& out) {
  const auto& ts = set.translational;
  int rows = 0;
  for (const auto& f : ts) {
    if (f.kind == FundamentalKind::kPointPlane)
      rows += 1;
    else if (f.exact() && tol.zeroLength(f.value()))
      rows += f.kind == FundamentalKind::kPointLine ? 2 : 3;
    else
      return false;
  }
  if (rows > 3 || ts.size() > 3) return false;
  for (std::size_t i = 0; i < ts.size(); ++i)
    for (std::size_t j = i + 1; j < ts.size(); ++j)
      if (ts[i].kind != FundamentalKind::kPointPoint &&
          ts[j].kind != FundamentalKind::kPointPoint &&
          !holdsForEveryRotation(ts[i], ts[j], rots, tol,
                                 [](const Vector3d&, const Vector3d&) { return true; }))
        return false;
  FixedVector<Fundamental, 3> linear;
  for (const auto& f : ts) linear.push_back(f);
  out = translation::Planes(linear);
  // Independent normals (checked at one rotation: their relative orientation is fixed).
  const Matrix3d R = rots.parts[0].baseRotation();
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  int k = 0;
  for (const auto& f : ts) {
    const TShape s = shapeOf(f, R);
    if (f.kind == FundamentalKind::kPointPlane)
      N.row(k++) = s.d.transpose();
    else if (f.kind == FundamentalKind::kPointLine) {
      N.row(k++) = s.e1.transpose();
      N.row(k++) = s.d.cross(s.e1).transpose();
    } else {
      for (int a = 0; a < 3; ++a) N.row(k++) = Vector3d::Unit(a).transpose();
    }
  }
  // Orthonormal rows (a box's three planes, a seam's two and its ends' range: the common case)
  // are independent; the SVD (about 5 % of such a solve) is for the others.
  const Matrix3d gram = N * N.transpose();
  bool orthonormal = true;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      orthonormal = orthonormal && std::abs(gram(i, j) - (i == j ? 1.0 : 0.0)) <= 1e-12;
  if (orthonormal) return true;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(N.topRows(3));
  const auto sv = svd.singularValues();
  int rank = 0;
  // A normal within the angle tolerance of the others' span leaves a singular value below it.
  const double independent = given.angleAboveRounding() * std::max(1.0, sv[0]);
  for (int i = 0; i < 3; ++i) rank += sv[i] > independent;
  return rank == k;
}

// A point-line distance and a point-plane constraint on the same point, at least one of them a
// range, with the line crossing the plane for every rotation: a bounded cylinder — a circle, an
// annulus, a finite (thick) cylinder, cut square or obliquely (Somani 004 Table VII, last row).
bool matchBoundedCylinder(const ConstraintSet& set, const Tolerance& tol,
                          const RotationAlternatives& rots, TranslationPart& out) {
  const auto& ts = set.translational;
  if (ts.size() != 2 || (ts[0].exact() && ts[1].exact())) return false;
  const int line = ts[0].kind == FundamentalKind::kPointLine ? 0 : 1;
  const Fundamental& cyl = ts[line];
  const Fundamental& pl = ts[1 - line];
  if (cyl.kind != FundamentalKind::kPointLine || pl.kind != FundamentalKind::kPointPlane ||
      (cyl.p - pl.p).norm() > tol.length || cyl.point_side != pl.point_side)
    return false;
  if (!holdsForEveryRotation(cyl, pl, rots, tol, [&](const Vector3d& d, const Vector3d& n) {
        return std::abs(d.dot(n)) > tol.angle;
      }))
    return false;
  out = translation::BoundedCylinder(cyl, pl);
  return true;
}

// Two translational constraints on different mobile points a and b whose shapes in translation
// space (T = X − R p) meet only for some rotations (issue 16): a sphere and a sphere, or a sphere
// and a plane. Their centres (and the plane's offset) move with R C, C the mobile vector from a's
// point to b's, so they meet exactly where the angle of R C from a fixed direction lies in a band:
// an implicit angle range. The set is then the rotations meeting it and the rotational
// constraints together, and for each the circle where the shapes meet.
enum class Meet { kNever, kSome, kAlways, kNotThisCase };

Meet circleCondition(const Fundamental& a0, const Fundamental& b0, const Tolerance& tol,
                     Fundamental* range, const Fundamental** sphere, const Fundamental** other) {
  auto isSphere = [&](const Fundamental& f) {
    return f.kind == FundamentalKind::kPointPoint && f.exact() && f.value() > tol.length;
  };
  auto isPlane = [](const Fundamental& f) {
    return f.kind == FundamentalKind::kPointPlane && f.exact() && f.point_side == Side::kMobile;
  };
  const bool swap = !isSphere(a0);
  const Fundamental& a = swap ? b0 : a0;
  const Fundamental& b = swap ? a0 : b0;
  if (!isSphere(a) || !(isSphere(b) || isPlane(b))) return Meet::kNotThisCase;
  const Vector3d C = b.p - a.p;  // mobile
  const double c = C.norm();
  if (c <= tol.length) return Meet::kNotThisCase;  // one point: the shapes keep their relation
  *sphere = &a;
  *other = &b;
  // u·R C ∈ [lo, hi] for a fixed unit u.
  Vector3d u;
  double lo, hi;
  if (isSphere(b)) {
    // |E − R C|² = |E|² + |C|² − 2 E·R C between (ra − rb)² and (ra + rb)², E = b.q − a.q.
    const Vector3d E = b.q - a.q;
    const double e = E.norm(), ra = a.value(), rb = b.value();
    const double base = E.squaredNorm() + C.squaredNorm();
    if (e <= tol.length) {
      const double d2 = C.squaredNorm();
      const bool meet = d2 >= (ra - rb) * (ra - rb) - tol.length * (ra + rb + c) &&
                        d2 <= (ra + rb) * (ra + rb) + tol.length * (ra + rb + c);
      return meet ? Meet::kAlways : Meet::kNever;
    }
    u = E / e;
    lo = (base - (ra + rb) * (ra + rb)) / (2.0 * e);
    hi = (base - (ra - rb) * (ra - rb)) / (2.0 * e);
  } else {
    // |n·(centre) − plane offset| ≤ ra: n·R C ∈ n·(b.q − a.q) ± ra.
    u = b.d;
    const double k = b.d.dot(b.q - a.q);
    lo = k - a.value();
    hi = k + a.value();
  }
  // cos of the angle of R Ĉ from u in [lo / c, hi / c].
  const double slack = tol.length / c;
  if (lo / c > 1.0 + slack || hi / c < -1.0 - slack) return Meet::kNever;
  if (lo / c <= -1.0 && hi / c >= 1.0) return Meet::kAlways;
  *range = Fundamental::angle(C / c, u, 0.0, a.sources | b.sources);
  range->lo = std::acos(clampUnit(hi / c));
  range->hi = std::acos(clampUnit(lo / c));
  // The band's edges come from lengths known to the tolerance: seen from the points' span.
  range->err = a.err + b.err + slack;
  return Meet::kSome;
}

MatchResult matchCircle(MatchContext& ctx) {
  const auto& ts = ctx.set.translational;
  if (ts.size() != 2 || ctx.set.revolve) return MatchResult::kNoMatch;
  Fundamental range;
  const Fundamental *sphere = nullptr, *other = nullptr;
  const Meet meet = circleCondition(ts[0], ts[1], ctx.tol, &range, &sphere, &other);
  if (meet == Meet::kNotThisCase) return MatchResult::kNoMatch;
  if (meet == Meet::kNever)
    return inconsistent(ctx, ts[0].sources | ts[1].sources,
                        "two distances on two mobile points that no rotation lets both hold");
  ConstraintSet with_range = ctx.set;
  if (meet == Meet::kSome) {
    if (with_range.rotational.full()) return MatchResult::kNoMatch;
    with_range.rotational.push_back(range);
  }
  MatchContext sub{with_range, ctx.tol, ctx.branches};
  RotationAlternatives rots;
  const MatchResult r = matchRotation(sub, rots);
  if (r == MatchResult::kInconsistent) {
    ctx.conflict = sub.conflict;
    ctx.reason = sub.reason;
  }
  if (r != MatchResult::kMatched) return r;
  translation::Circle circle(*sphere, *other);
  // Touching shapes (r² − along² within what the tolerance leaves of it) are one point.
  circle.snap_radius = std::sqrt(2.0 * sphere->value() * ctx.tol.length);
  for (int k = 0; k < rots.size(); ++k)
    if (!ctx.branches.add<SeparableManifold>(rots.parts[k], circle)) return MatchResult::kOverflow;
  return MatchResult::kMatched;
}

bool hasKind(const ConstraintSet& set, FundamentalKind kind) {
  for (const auto& f : set.translational)
    if (f.kind == kind) return true;
  return false;
}

MatchResult matchSeparable(MatchContext& ctx, const void* /*context*/) {
  RotationAlternatives rots;
  MatchResult r = matchRotation(ctx, rots);
  if (r != MatchResult::kMatched) return r;
  TranslationPart trans;
  // Directions the rotation carries are known to its uncertainty (a spin axis derived where two
  // cones barely meet): the translational elements' directions are compared within it.
  double rot_err = 0.0;
  for (int k = 0; k < rots.size(); ++k) rot_err = std::max(rot_err, rots.err[k]);
  const Tolerance tol = ctx.tol.widened(rot_err);
  // A line-line distance is mixed (not separable) until the rotation fixes its mobile direction.
  if (hasKind(ctx.set, FundamentalKind::kLineLine) ||
      (!matchTranslation(ctx.set, tol, rots, trans) &&
       !matchPlanes(ctx.set, tol, ctx.tol, rots, trans) &&
       !matchBoundedCylinder(ctx.set, tol, rots, trans))) {
    if (!hasKind(ctx.set, FundamentalKind::kLineLine)) {
      r = matchCircle(ctx);
      if (r != MatchResult::kNoMatch) return r;
    }
    r = detail::reanchorForEachRotation(ctx, rots);
    return r != MatchResult::kNoMatch ? r : detail::revolveForEachRotation(ctx, rots);
  }
  for (int k = 0; k < rots.size(); ++k) {
    if (ctx.set.revolve && !rots.parts[k].is<rotation::Fixed>()) return MatchResult::kNoMatch;
    const bool added =
        ctx.set.revolve
            ? ctx.branches.add<RevolvedManifold>(ctx.set.revolve_point, ctx.set.revolve_axis,
                                                 SeparableManifold(rots.parts[k], trans))
            : ctx.branches.add<SeparableManifold>(rots.parts[k], trans);
    if (!added) return MatchResult::kOverflow;
  }
  return MatchResult::kMatched;
}

}  // namespace

void registerBuiltinManifolds(Registry& registry) {
  for (ManifoldInfo& m : separableShapeCatalogue()) registry.addManifold(std::move(m));
  registry.addMatcher({"separable", &matchSeparable});
}

}  // namespace relpos::manifolds
