// PMF App. IV Table VII and Fig. 3: two point-plane coincidences d(P_a, Σ_b) = 0,
// d(Q_a, Π_b) = 0 (both points on one object, both planes on the other).
#include <cmath>

#include "family.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pplane_pplane_family {
using namespace detail;

enum Case { kIncompatible, kSamePlane, kPlanesMeet, kParallelSpan };

// Fig. 3c: the one point of a and b on the line where their planes meet (cross = n_a × n_b).
// Across the planes, that line is known to rounding / sin θ: deferred where that is too much.
void onLineWherePlanesMeet(const Fundamental& a, const Fundamental& b, const Vector3d& cross,
                           const Tolerance& tol, RuleOutput& out) {
  if (tol.tooIllConditioned(1.0 / cross.norm())) return out.defer();
  one(out.fire(kPlanesMeet),
      withErr(onLine(a, pointWherePlanesMeet(a.q, a.d, b.q, b.d), cross.normalized(), 0),
              tol.length / cross.norm()));
}

void twoPointPlane(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out) {
  if (!sameRoles(a, b)) return;  // mixed roles: not a PMF table
  const double da = (b.p - a.p).norm();
  const Vector3d cross = accurateCross(a.d, b.d);
  if (!tol.parallelUnit(cross.norm())) {
    // Fig. 3c: the same point on two planes lies on their intersection line.
    if (da > tol.length) return;  // different points: the matcher's plane∩plane line
    return onLineWherePlanesMeet(a, b, cross, tol, out);
  }
  const Vector3d& n = a.d;
  // Signed distance from Σ to Π along Σ's normal, read where the problem is (Π's point nearest
  // the origin: the solver centres the geometry), for planes parallel within the angle tolerance.
  const Vector3d b0 = b.q.dot(b.d) * b.d;
  const double db = (b0 - a.q).dot(n);
  if (da <= tol.length) {
    if (std::abs(db) <= tol.length) return out.fire(kSamePlane).redundantSecond();  // Fig. 3b
    // Apart here but not exactly parallel: they meet further away — unless parallel to rounding
    // (1e-12, as in pl+pl): then they are parallel, and where they would meet is rounding over
    // rounding.
    if (Tolerance::tiltedBeyondRounding(cross.norm()))
      return onLineWherePlanesMeet(a, b, cross, tol, out);
    return out.fire(kIncompatible)
        .incompatible("one point on two distinct parallel planes (PMF App. IV Table VII)");
  }
  // Planes parallel only within the tolerance drift apart by sin θ along them, and nothing in
  // this pair bounds where on them the points lie (the planes even meet far away, where any span
  // fits): the distance read at the centre is the points' only there, neither a span nor a
  // conflict (as pl+pl's parallel lines). Left to the other rules and the matchers; planes
  // parallel to rounding are read as before.
  if (Tolerance::tiltedBeyondRounding(cross.norm())) return out.defer();
  double alpha;
  if (!acosChecked(db, da, tol.length, &alpha))  // Fig. 3a: d_a < d_b
    return out.fire(kIncompatible)
        .incompatible(
            "two points closer together than the distance between the parallel planes they must "
            "lie "
            "on (PMF App. IV Table VII, Fig. 3a)");
  // Fig. 3d: the implicit rotation ∠(u_a, n) = acos(d_b / d_a) makes Q's plane follow from P's.
  const Vector3d u_a = (b.p - a.p) / da;
  // (The planes are parallel only within the angle tolerance: the angle read off Σ's normal is
  // off from Π's by up to the angle between them, sin θ = |cross|.)
  two(out.fire(kParallelSpan), a,
      withErr(angleAB(a.point_side, u_a, n, alpha), heightAngleErr(db, da, tol) + cross.norm()));
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table VII, row 1 (Fig. 3a)"},
    {kSamePlane, "same-plane", "PMF App. IV Table VII, row 2 (Fig. 3b)"},
    {kPlanesMeet, "planes-meet", "PMF App. IV Table VII, row 3 (Fig. 3c)"},
    {kParallelSpan, "parallel-span", "PMF App. IV Table VII, rows 4 and 5 (Fig. 3d)"}};

}  // namespace pplane_pplane_family

constexpr RuleFamily families::pplane_pplane =
    family("pplane+pplane", "PMF App. IV Table VII, Fig. 3", FundamentalKind::kPointPlane,
           FundamentalKind::kPointPlane,
           &pplane_pplane_family::withLengthErr<pplane_pplane_family::twoPointPlane>,
           pplane_pplane_family::kCases);

}  // namespace relpos::rules
