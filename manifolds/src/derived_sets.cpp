#include "derived_sets.hpp"

#include <algorithm>

#include "relpos/core/branch_sink.hpp"

namespace relpos::manifolds::detail {
namespace {

// With the rotation known, every translational constraint confines T to a fixed shape: re-anchor
// them all to the mobile frame's origin (T = R·0 + T), where the one-point rules of PMF App. IV
// apply whatever points, roles and frames the constraints had (PMF §V: T is solved for the
// current R).
Fundamental reanchored(const Fundamental& f, const Matrix3d& R) {
  Fundamental g = f;
  if (f.point_side == Side::kMobile) {
    g.q = f.q - R * f.p;  // fixed element shifted by the mobile point's offset
  } else {
    g.q = f.p - R * f.q;  // T on the shape p − R X: point p_f, element moved by R
    g.d = R * f.d;
    if (f.kind == FundamentalKind::kPointPlane) {
      // (p − R q − T)·Rn = v  <=>  (T − (p − R q))·Rn = −v: a signed range flips.
      g.lo = -f.hi;
      g.hi = -f.lo;
    }
  }
  g.point_side = Side::kMobile;
  g.p = Vector3d::Zero();
  return g;
}

// The origin at a signed distance in [lo, hi] from the plane (q, n); exact ones folded to 0.
Fundamental planeOfOrigin(const Vector3d& q, const Vector3d& n, double lo, double hi,
                          SourceMask s) {
  if (lo == hi) return Fundamental::pointPlane(Side::kMobile, Vector3d::Zero(), q, n, lo, s);
  Fundamental g = Fundamental::pointPlane(Side::kMobile, Vector3d::Zero(), q, n, 0.0, s);
  g.lo = lo;
  g.hi = hi;
  return g;
}

// The shapes of T for one translational constraint under a known rotation R (1 or 2
// alternatives). A line-line distance (Somani's mixed constraint) stops being mixed: with the
// mobile line's direction w = R u known, the distance is |(T + R p − q)·n| for n ∥ d × w (two
// planes, or two slabs for a range), or the distance of T + R p from the fixed line when w ∥ d.
int shapesOf(const Fundamental& f, const Matrix3d& R, const Tolerance& tol, Fundamental out[2]) {
  if (f.kind != FundamentalKind::kLineLine) {
    out[0] = reanchored(f, R);
    return 1;
  }
  const Vector3d w = R * f.u, q = f.q - R * f.p, n = f.d.cross(w);
  if (tol.parallelUnit(n.norm())) {
    out[0] = Fundamental::pointLine(Side::kMobile, Vector3d::Zero(), q, f.d, f.lo, f.sources);
    out[0].hi = f.hi;
    return 1;
  }
  if (f.lo == 0.0) {
    out[0] = planeOfOrigin(q, n, -f.hi, f.hi, f.sources);
    return 1;
  }
  out[0] = planeOfOrigin(q, n, f.lo, f.hi, f.sources);
  out[1] = planeOfOrigin(q, n, -f.hi, -f.lo, f.sources);
  return 2;
}

bool anchored(const ConstraintSet& set) {
  for (const auto& f : set.translational)
    if (f.point_side != Side::kMobile || !f.p.isZero(0.0) || f.kind == FundamentalKind::kLineLine)
      return false;
  return true;
}

// The longest lever a rotation turns in the set's translational constraints: the mobile points
// and mobile elements' points (centred: measured from the middle of the mobile features).
double mobileLever(const ConstraintSet& set) {
  double lever = 0.0;
  for (const auto& f : set.translational)
    lever = std::max(lever, (f.point_side == Side::kMobile ? f.p : f.q).norm());
  return lever;
}

// The set for the rotation R, known to `err` rad: it rides along as two parallelisms (the
// original rotational constraints are all summed up in R) carrying that uncertainty, and its
// lengths are decided within what that turns the mobile features by (err × `lever`).
void startDerived(const ConstraintSet& set, const Matrix3d& R, double err, double lever,
                  ConstraintSet& derived) {
  SourceMask rot_sources = 0;
  for (const auto& f : set.rotational) rot_sources |= f.sources;
  derived.clear();
  derived.dropped_redundant = set.dropped_redundant;
  derived.revolve = set.revolve;
  derived.revolve_point = set.revolve_point;
  derived.revolve_axis = set.revolve_axis;
  derived.slack = set.slack + err * lever;
  Fundamental x = Fundamental::angle(Vector3d::UnitX(), R.col(0), 0.0, rot_sources);
  Fundamental y = Fundamental::angle(Vector3d::UnitY(), R.col(1), 0.0, rot_sources);
  x.err = y.err = err;
  derived.add(x);
  derived.add(y);
}

// A point of the line about which constraint f is invariant, if f pins one; false when f is not
// invariant under turning about any line along a. A line or plane normal parallel to a only
// within the tolerance, tilted beyond rounding, is not: turned about a, it sweeps a cone that
// leaves it by twice its tilt times the distance along it (seed offset 41: two lines 1e-9 rad
// apart taken as one axis, their points 0.27 apart along it turned 5.7e-10 off the second line
// at the turn the derived set was solved for, more than the tolerance: a feasible problem was
// `inconsistent`).
bool invariantAbout(const Fundamental& f, const Vector3d& a, const Tolerance& tol, bool* pins,
                    Vector3d* point) {
  *pins = true;
  if (f.point_side == Side::kFixed) {  // a fixed point measured against a mobile element
    *point = f.p;
    return true;
  }
  *point = f.q;
  const double tilt = f.d.cross(a).norm();
  const bool along = tol.parallelUnit(tilt) && !Tolerance::tiltedBeyondRounding(tilt);
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      return true;
    case FundamentalKind::kPointLine:
    case FundamentalKind::kLineLine:
      return along;
    case FundamentalKind::kPointPlane:
      *pins = false;
      return along;
    default:
      return false;
  }
}

// The line (point c, direction a) about which every translational constraint is invariant.
bool revolveLine(const ConstraintSet& set, const Vector3d& a, const Tolerance& tol, Vector3d* c) {
  bool pinned = false;
  *c = Vector3d::Zero();
  for (const auto& f : set.translational) {
    bool pins = false;
    Vector3d point;
    if (!invariantAbout(f, a, tol, &pins, &point)) return false;
    if (!pins) continue;
    if (!pinned) {
      *c = point;
      pinned = true;
    } else if ((point - *c).cross(a).norm() > tol.length) {
      return false;
    }
  }
  return true;
}

}  // namespace

MatchResult reanchorForEachRotation(MatchContext& ctx, const RotationAlternatives& rots) {
  if (!ctx.branches.canDefer() || anchored(ctx.set)) return MatchResult::kNoMatch;
  for (int k = 0; k < rots.size(); ++k)
    if (!rots.parts[k].is<rotation::Fixed>()) return MatchResult::kNoMatch;
  const auto& ts = ctx.set.translational;
  Fundamental shapes[kMaxFundamentals][2];
  int n_shapes[kMaxFundamentals];
  ConstraintSet derived;
  const double lever = mobileLever(ctx.set);
  for (int k = 0; k < rots.size(); ++k) {
    const Matrix3d& R = rots.parts[k].as<rotation::Fixed>()->R0;
    // One derived set per choice of side for every two-sided shape (a mixed odometer).
    int combos = 1;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      n_shapes[i] = shapesOf(ts[i], R, ctx.tol, shapes[i]);
      combos *= n_shapes[i];
      if (combos > static_cast<int>(ctx.branches.maxBranches())) return MatchResult::kOverflow;
    }
    for (int combo = 0; combo < combos; ++combo) {
      startDerived(ctx.set, R, rots.err[k], lever, derived);
      for (std::size_t i = 0, rest = combo; i < ts.size(); ++i) {
        derived.add(shapes[i][rest % n_shapes[i]]);
        rest /= n_shapes[i];
      }
      if (!ctx.branches.defer(derived)) return MatchResult::kOverflow;
    }
  }
  return MatchResult::kDeferred;
}

MatchResult revolveForEachRotation(MatchContext& ctx, const RotationAlternatives& rots) {
  if (!ctx.branches.canDefer() || ctx.set.revolve || rots.size() == 0) return MatchResult::kNoMatch;
  Vector3d c[kMaxRotations];
  for (int k = 0; k < rots.size(); ++k) {
    const auto* spin = rots.parts[k].as<rotation::OneParallel>();
    // A spin over an arc (a range on another vector) would need the revolved branch's turn
    // bounded to it: not yet.
    if (!spin || !spin->phi_periodic || !revolveLine(ctx.set, spin->u_f, ctx.tol, &c[k]))
      return MatchResult::kNoMatch;
  }
  ConstraintSet derived;
  const double lever = mobileLever(ctx.set);
  for (int k = 0; k < rots.size(); ++k) {
    const auto& spin = *rots.parts[k].as<rotation::OneParallel>();
    startDerived(ctx.set, spin.R0, rots.err[k], lever, derived);
    derived.revolve = true;
    derived.revolve_point = c[k];
    derived.revolve_axis = spin.u_f;
    for (const auto& f : ctx.set.translational) derived.add(f);
    if (!ctx.branches.defer(derived)) return MatchResult::kOverflow;
  }
  return MatchResult::kDeferred;
}

}  // namespace relpos::manifolds::detail
