#pragma once
// Fundamental constraints (PMF §III): the pure translational distances point–point, point–line
// and point–plane, and the pure rotational vector–vector angle. Each side is tagged fixed or
// mobile: fixed geometry is in world coordinates, mobile geometry in the mobile object's frame
// M, so a candidate pose X_WM = (R, T) maps a mobile point p to R p + T.
#include <cstdint>

#include "relpos/core/fixed_vector.hpp"
#include "relpos/core/geometry.hpp"

namespace relpos {

// Bit i set = input constraint i contributed. Problems with more than 64 constraints are
// answered `unhandled` by the solver.
using SourceMask = std::uint64_t;

enum class FundamentalKind : unsigned char {
  kPointPoint = 0,  // |p - q| in [lo, hi]
  kPointLine = 1,   // distance(p, line(q, d)) in [lo, hi]
  kPointPlane = 2,  // (p - q) . d in [lo, hi], plane (q, d); exact ones are normalised to 0
  kAngle = 3,       // angle(R u_m, u_f) in [lo, hi]
  // Somani's mixed constraint: the (skew) distance between a mobile line (p, u) and a fixed line
  // (q, d) in [lo, hi]. Neither purely rotational nor translational; kept in C_T, never combined
  // by the PMF rules, solved by the mixed-manifold matcher.
  kLineLine = 4,
  // A kind a plugin registers (Registry::addCustomKind): `custom` names which. The built-in rules
  // and matchers never touch it; only the plugin's own rules and matchers do, so a set holding
  // one that no plugin matcher recognises is answered `unhandled`, never solved without it.
  kCustom = 5,
};
inline constexpr int kFundamentalKinds = 6;
const char* toString(FundamentalKind k);

enum class Side : unsigned char { kFixed, kMobile };

struct Fundamental {
  FundamentalKind kind = FundamentalKind::kPointPoint;
  // Translational: the side that owns the point p ("a" in PMF); the other element (q, d) belongs
  // to the other side ("b"). Point–point constraints are stored with the point p mobile.
  // Angle: p = u_m (mobile vector), q = u_f (fixed vector); point_side unused.
  Side point_side = Side::kMobile;
  Vector3d p = Vector3d::Zero();
  Vector3d q = Vector3d::Zero();
  Vector3d d = Vector3d::UnitZ();
  Vector3d u = Vector3d::UnitZ();  // kLineLine: the mobile line's direction
  double lo = 0.0, hi = 0.0;
  // How far an angle constraint's vectors (or value) may be from those of the problem as given,
  // in radians, because a rule derived them from lengths: the direction of a span d_a long is
  // known to (length tolerance) / d_a, and an angle read off a cosine near ±1 to its square root.
  // Rules and matchers widen their angle comparisons by it (a derived parallelism 1e-8 long is no
  // parallelism to 1e-9 rad), and where they must break one constraint to keep another, they keep
  // the one known best. 0 for what the user gave. For a translational constraint a rule derived
  // (a point pinned where a line meets a cylinder nearly tangentially), the same in lengths: how
  // far its point or element may be from the exact one.
  double err = 0.0;
  SourceMask sources = 0;
  std::uint16_t id = 0;      // identity within a constraint set (assigned by ConstraintSet::add)
  std::uint16_t custom = 0;  // kCustom: the index Registry::addCustomKind returned

  bool exact() const { return lo == hi; }
  double value() const { return lo; }
  bool translational() const { return kind != FundamentalKind::kAngle; }
  // The fixed side's point (world) and the mobile side's point (mobile frame) of a built-in
  // translational or line-line constraint; null for an angle (directions only) or a custom kind.
  Vector3d* fixedPoint();
  Vector3d* mobilePoint();
  // Moves the fixed point by offset_W and the mobile point by offset_M (directions and values do
  // not change): the same constraint between the moved geometries.
  void translate(const Vector3d& offset_W, const Vector3d& offset_M);

  static Fundamental pointPoint(const Vector3d& p_m, const Vector3d& q_f, double v, SourceMask s);
  static Fundamental pointLine(Side point_side, const Vector3d& p, const Vector3d& a,
                               const Vector3d& d, double v, SourceMask s);
  // Exact point-plane: plane through a with normal n, signed offset v folded into the plane.
  static Fundamental pointPlane(Side point_side, const Vector3d& p, const Vector3d& a,
                                const Vector3d& n, double v, SourceMask s);
  static Fundamental angle(const Vector3d& u_m, const Vector3d& u_f, double alpha, SourceMask s);
  static Fundamental lineLine(const Vector3d& a_m, const Vector3d& u_m, const Vector3d& a_f,
                              const Vector3d& d_f, double lo, double hi, SourceMask s);
};

// Capacity of a constraint set: twice the 8 constraints of the allocation-free target leaves
// room for the extra constraints rules add (implicit rotations, either-alternatives).
inline constexpr std::size_t kMaxFundamentals = 24;

struct ConstraintSet {
  // User-provided: value-initialising a set (emplace_back(), `{}`) would otherwise zero its
  // 7 KB of slots first, a fifth of a small solve.
  ConstraintSet() noexcept {}                                // NOLINT(modernize-use-equals-default)
  FixedVector<Fundamental, kMaxFundamentals> translational;  // C_T
  FixedVector<Fundamental, kMaxFundamentals> rotational;     // C_R
  // Pairs (by id) already tested without any rule applying: not tested again, also not after a
  // branch (PMF 003 §VII-A). Best effort: when full, pairs are simply re-tested.
  FixedVector<std::uint32_t, 96> tested;
  SourceMask dropped_redundant = 0;  // sources of constraints dropped
  std::uint16_t next_id = 1;
  bool overflow = false;  // a push_back was refused
  // Set on the sets a matcher derives for a one-parallelism rotation whose constraints are all
  // invariant under turning about one fixed line (Somani 004 Fig. 2c): the set then describes
  // X' of X = Rot(line, phi) X', and every branch matched from it must be a revolved manifold.
  bool revolve = false;
  Vector3d revolve_point = Vector3d::Zero(), revolve_axis = Vector3d::UnitZ();
  // How far the set's geometry may be from the problem's, in lengths, because a matcher derived
  // it under a rotation known only to an uncertainty (re-anchoring after two derived
  // parallelisms): the solver decides the set's lengths within the tolerance plus this, so that
  // the rotation's error is not read as a violation. 0 for the sets the constraints decompose to.
  double slack = 0.0;
  void clear() {
    translational.clear();
    rotational.clear();
    tested.clear();
    dropped_redundant = 0;
    next_id = 1;
    overflow = false;
    revolve = false;
    slack = 0.0;
  }
  void add(Fundamental f) {
    f.id = next_id++;
    bool ok = f.translational() ? translational.push_back(f) : rotational.push_back(f);
    overflow = overflow || !ok;
  }
  static std::uint32_t pairKey(const Fundamental& a, const Fundamental& b) {
    return a.id < b.id ? (std::uint32_t{a.id} << 16 | b.id) : (std::uint32_t{b.id} << 16 | a.id);
  }
  bool wasTested(const Fundamental& a, const Fundamental& b) const {
    const std::uint32_t k = pairKey(a, b);
    for (std::uint32_t t : tested)
      if (t == k) return true;
    return false;
  }
  void markTested(const Fundamental& a, const Fundamental& b) { tested.push_back(pairKey(a, b)); }
  SourceMask usedSources() const;
};

}  // namespace relpos
