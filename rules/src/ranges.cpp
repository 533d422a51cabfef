// Somani et al. (004) Table VII, first rows: two constraints on the same point whose loci are
// concentric — parallel planes, the same centre, the same axis — with at least one range. The
// allowed values form one interval each; their intersection decides: empty → incompatible, one
// inside the other → the wider is redundant, else a single range on the overlap.
#include <algorithm>
#include <cmath>

#include "relpos/rules/builtin.hpp"
#include "rule_helpers.hpp"

namespace relpos::rules {
namespace {
using namespace detail;

enum Case { kDisjoint, kNested, kOverlap };

struct Interval {
  double lo, hi;
};

// Decides two intervals of the same quantity (the first constraint's), writing the overlap into
// `both`. Returns false when the rule made its decision without a replacement.
bool intersect(Interval a, Interval b, const Tolerance& tol, RuleOutput& out, Interval* both) {
  both->lo = std::max(a.lo, b.lo);
  both->hi = std::min(a.hi, b.hi);
  if (both->lo > both->hi + tol.length) {
    out.fire(kDisjoint).incompatible(
        "two ranges on the same distance that do not overlap (Somani 004 Table VII)");
    return false;
  }
  if (both->hi < both->lo) both->hi = both->lo;
  auto inside = [&](Interval x, Interval y) {  // x ⊆ y
    return x.lo >= y.lo - tol.length && x.hi <= y.hi + tol.length;
  };
  if (inside(a, b)) {
    out.fire(kNested).redundantSecond();
    return false;
  }
  if (inside(b, a)) {
    out.fire(kNested).redundantFirst();
    return false;
  }
  out.fire(kOverlap);
  return true;
}

// A point-plane constraint with the overlap [lo, hi] on the first constraint's plane; a single
// value becomes an exact (folded) coincidence.
Fundamental planeRange(const Fundamental& a, Interval v, const Tolerance& tol) {
  if (v.hi - v.lo <= tol.length)
    return Fundamental::pointPlane(a.point_side, a.p, a.q, a.d, 0.5 * (v.lo + v.hi), a.sources);
  Fundamental f = Fundamental::pointPlane(a.point_side, a.p, a.q, a.d, 0.0, a.sources);
  f.lo = v.lo;
  f.hi = v.hi;
  return f;
}

Fundamental distanceRange(const Fundamental& a, Interval v, const Tolerance& tol) {
  Fundamental f = a;
  if (v.hi - v.lo <= tol.length) v.lo = v.hi = 0.5 * (v.lo + v.hi);
  f.lo = v.lo;
  f.hi = v.hi;
  return f;
}

bool bothExact(const Fundamental& a, const Fundamental& b) { return a.exact() && b.exact(); }

void parallelSlabs(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                   RuleOutput& out) {
  if (bothExact(a, b) || !sameRoles(a, b) || (a.p - b.p).norm() > tol.length) return;
  if (!tol.parallelUnit(a.d.cross(b.d).norm())) return;  // crossing slabs: a parallelepiped
  // In a's reading t = (P − q_a)·n_a: b's values map by its orientation and plane offset.
  const double s = a.d.dot(b.d) > 0 ? 1.0 : -1.0;
  const double off = (b.q - a.q).dot(a.d);
  Interval ib{s * b.lo + off, s * b.hi + off};
  if (ib.lo > ib.hi) std::swap(ib.lo, ib.hi);
  Interval both;
  if (intersect({a.lo, a.hi}, ib, tol, out, &both)) one(out, planeRange(a, both, tol));
}

void concentricSpheres(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                       RuleOutput& out) {
  if (bothExact(a, b) || (a.p - b.p).norm() > tol.length || (a.q - b.q).norm() > tol.length) return;
  Interval both;
  if (intersect({a.lo, a.hi}, {b.lo, b.hi}, tol, out, &both)) one(out, distanceRange(a, both, tol));
}

void coaxialCylinders(const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                      RuleOutput& out) {
  if (bothExact(a, b) || !sameRoles(a, b) || (a.p - b.p).norm() > tol.length) return;
  const Vector3d w = b.q - a.q;
  if (!tol.parallelUnit(a.d.cross(b.d).norm()) || (w - w.dot(a.d) * a.d).norm() > tol.length)
    return;
  Interval both;
  if (intersect({a.lo, a.hi}, {b.lo, b.hi}, tol, out, &both)) one(out, distanceRange(a, both, tol));
}

std::vector<RuleCase> cases(const std::string& family, const char* what) {
  return {
      {family + "/disjoint", std::string("Somani 004 Table VII, ") + what + ": disjoint ranges"},
      {family + "/nested", std::string("Somani 004 Table VII, ") + what + ": nested ranges"},
      {family + "/overlap", std::string("Somani 004 Table VII, ") + what + ": overlapping ranges"}};
}

}  // namespace

void registerRangeRules(Registry& r) {
  using FK = FundamentalKind;
  addFamily(r, "range:pplane+pplane", "Somani 004 Table VII (PMF-style limit cases)",
            FK::kPointPlane, FK::kPointPlane, &parallelSlabs,
            cases("range:pplane+pplane", "parallel plane ranges"), true);
  addFamily(r, "range:pp+pp", "Somani 004 Table VII", FK::kPointPoint, FK::kPointPoint,
            &concentricSpheres, cases("range:pp+pp", "concentric distance ranges"), true);
  addFamily(r, "range:pl+pl", "Somani 004 Table VII", FK::kPointLine, FK::kPointLine,
            &coaxialCylinders, cases("range:pl+pl", "coaxial distance ranges"), true);
}

}  // namespace relpos::rules
