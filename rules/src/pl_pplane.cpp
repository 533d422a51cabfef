// PMF App. IV Table VI: a point-line distance and a point-plane coincidence,
// d(P_a, K_b) = p, d(Q_a, Π_b) = 0, both points on object a. When K_b ∥ Π_b, d_b is the
// distance between them; otherwise the line meets the plane.
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pl_pplane_family {
using namespace detail;

enum Case { kIncompatible, kLineMeetsPlane, kImplied, kLinesOnPlane, kParallelSpan, kStretched };

void pointLineAndPointPlane(const Fundamental& pl, const Fundamental& pp, const Tolerance& tol,
                            RuleOutput& out) {
  if (!sameRoles(pl, pp)) return;  // mixed roles: Table IX
  const double p = pl.value();
  const double da = (pp.p - pl.p).norm();
  const Vector3d& n = pp.d;
  const double dn = pl.d.dot(n);
  const bool one_point_on_both = da <= tol.length && tol.zeroLength(p);
  // The one point where the line crosses the plane; along the line, known to rounding / |d·n|.
  auto pinAtCrossing = [&] {
    if (tol.tooIllConditioned(1.0 / std::abs(dn))) return out.defer();
    const Vector3d x = pl.q + ((pp.q - pl.q).dot(n) / dn) * pl.d;
    // The plane's height known to the tolerance moves the crossing by that over |d·n|.
    return one(out.fire(kLineMeetsPlane), withErr(pinPoint(pl, x), tol.length / std::abs(dn)));
  };
  if (std::abs(dn) > tol.angle) {
    if (one_point_on_both) return pinAtCrossing();
    return;  // an ellipse, or a line and a plane on two points: the matcher's cases
  }
  // K_b ∥ Π_b: h = signed height of the line over the plane, read where the problem is (the
  // line's point nearest the origin: the solver centres the geometry), for a line parallel to
  // the plane only within the angle tolerance.
  const Vector3d k0 = projectOnLine(Vector3d::Zero(), pl.q, pl.d);
  const double h = (k0 - pp.q).dot(n);
  const double db = std::abs(h);
  // Two points, and a line parallel to the plane only within the tolerance: the line's height
  // over the plane drifts by |d·n| along it, and nothing in this pair bounds where along it the
  // points lie (it even crosses the plane far away, where any span fits): the height read at the
  // centre is the points' only there, neither a span nor a conflict (as pl+pl's parallel lines).
  // Left to the other rules and the matchers; lines parallel to rounding are read as before.
  const bool tilted = Tolerance::tiltedBeyondRounding(dn);
  if (da > tol.length && tilted) return out.defer();
  if (db - da > p + tol.length) {
    // Apart here but tilted: one point is where they cross further away, or (a distance from the
    // line) on the long ellipse the cylinder cuts from the plane there.
    if (tilted) return one_point_on_both ? pinAtCrossing() : out.defer();
    return out.fire(kIncompatible)
        .incompatible(
            "a point-line distance and a point-plane coincidence that no pose satisfies (PMF App. "
            "IV "
            "Table VI, row 1)");
  }
  const Vector3d foot = k0 - h * n;  // the line's shadow on the plane passes through here
  if (da <= tol.length) {
    // One point, and a line tilted beyond rounding: it crosses the plane at one point, and the
    // cylinder about it cuts the plane in a long ellipse, not lines — read as lying in the plane,
    // the point slid along it to where it had left the plane by more than the tolerance (as
    // pl+pl's lines crossing within the tolerance: seed offset 7505).
    if (tilted) return tol.zeroLength(p) ? pinAtCrossing() : out.defer();
    // One point: the cylinder about K_b cuts the plane in one or two lines ∥ K_b.
    if (tol.zeroLength(p)) return out.fire(kImplied).redundantSecond();  // K_b lies in Π_b
    out.fire(kLinesOnPlane);
    // Tangent, or beyond by no more than the tolerance (the check above allowed it).
    if (db >= p - tol.length) return one(out, onLine(pl, foot, pl.d, 0));
    const Vector3d v = pl.d.cross(n);
    const double k = std::sqrt(p * p - db * db);
    one(out, onLine(pl, foot + k * v, pl.d, 0));
    one(out, onLine(pl, foot - k * v, pl.d, 0));
    return;
  }
  if (tol.zeroLength(p)) {
    // P on the line, Q on the plane: the rotation keeps PQ at height −h over the line
    // (generalises rows 7 and 8); Q's plane then follows from P's line.
    double alpha;
    if (!acosChecked(-h, da, tol.length, &alpha))
      return out.fire(kIncompatible).incompatible("the plane is out of reach of the second point");
    const Vector3d u_a = (pp.p - pl.p) / da;
    // (The line is parallel to the plane only within the angle tolerance: the angle read off the
    // plane's normal is off by up to |d·n| more.)
    return two(
        out.fire(kParallelSpan), pl,
        withErr(angleAB(pl.point_side, u_a, n, alpha), heightAngleErr(h, da, tol) + std::abs(dn)));
  }
  if (db > tol.length && tol.equalLength(db - da, p)) {
    // P at p from K_b toward the plane, Q right below it on the plane.
    const Vector3d u_b = -(h / db) * n;
    const Vector3d R_b = k0 + p * u_b;  // on the line through K_b's point, toward the plane
    return two(out.fire(kStretched), onLine(pl, R_b, pl.d, 0), onLine(pp, foot, pl.d, 0));
  }
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table VI, row 1"},
    {kLineMeetsPlane, "line-meets-plane", "PMF App. IV Table VI, row 6 (K ∦ Π, d_a = 0, p = 0)"},
    {kImplied, "implied", "PMF App. IV Table VI (K in Π, d_a = 0, p = 0)"},
    {kLinesOnPlane, "lines-on-plane", "PMF App. IV Table VI, rows 3 and 4 (K ∥ Π, d_a = 0)"},
    {kParallelSpan, "parallel-span", "PMF App. IV Table VI, rows 7 and 8 (K ∥ Π, p = 0)"},
    {kStretched, "stretched", "PMF App. IV Table VI, row 2 (d_b − d_a = p)"}};

}  // namespace pl_pplane_family

constexpr RuleFamily families::pl_pplane = family(
    "pl+pplane", "PMF App. IV Table VI", FundamentalKind::kPointLine, FundamentalKind::kPointPlane,
    &pl_pplane_family::withLengthErr<pl_pplane_family::pointLineAndPointPlane>,
    pl_pplane_family::kCases);

}  // namespace relpos::rules
