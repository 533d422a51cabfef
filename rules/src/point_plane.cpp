// PMF App. IV Table VII and Fig. 3: two point-plane coincidences d(P_a, Σ_b) = 0,
// d(Q_a, Π_b) = 0 (both points on one object, both planes on the other).
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

void twoPointPlane(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out) {
  if (a.point_side != b.point_side) return;  // mixed roles: Tables VIII/IX
  const double da = (b.p - a.p).norm();
  const bool parallel = tol.parallelUnit(a.d.cross(b.d).norm());
  if (!parallel) {
    // Fig. 3c: the same point on two planes lies on their intersection line.
    if (da > tol.length) return;  // different points: the matcher's plane∩plane line
    const Vector3d dir = a.d.cross(b.d).normalized();
    // A point on both planes: solve in the span of the normals from a.q.
    const double n12 = a.d.dot(b.d), h2 = (b.q - a.q).dot(b.d), det = 1 - n12 * n12;
    const Vector3d c = a.q + (-h2 * n12 / det) * a.d + (h2 / det) * b.d;
    return one(out, onLine(a, c, dir, 0));
  }
  const Vector3d& n = a.d;
  const double db = (b.q - a.q).dot(n);  // signed distance from Σ to Π along Σ's normal
  if (da <= tol.length) {
    if (std::abs(db) <= tol.length) {  // Fig. 3b
      out.verdict = RuleVerdict::kRedundantSecond;
      return;
    }
    return out.incompatible("one point on two distinct parallel planes (PMF App. IV Table VII)");
  }
  double alpha;
  if (!acosChecked(db, da, tol.length, &alpha))  // Fig. 3a: d_a < d_b
    return out.incompatible("two points closer together than the distance between the parallel "
                            "planes they must lie on (PMF App. IV Table VII, Fig. 3a)");
  // Fig. 3d: the implicit rotation ∠(u_a, n) = acos(d_b / d_a) makes Q's plane follow from P's.
  const Vector3d u_a = (b.p - a.p) / da;
  two(out, a, angleAB(a.point_side, u_a, n, alpha));
}

}  // namespace

void registerPointPlaneRules(Registry& r) {
  r.addRule({"pplane+pplane/two-coincidences", "PMF App. IV Table VII, Fig. 3 (b)-(d)",
             FundamentalKind::kPointPlane, FundamentalKind::kPointPlane, &twoPointPlane});
}

}  // namespace relpos::rules
