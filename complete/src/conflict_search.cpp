#include "conflict_search.hpp"

#include <algorithm>
#include <cmath>

#include "set_exclusion.hpp"

namespace relpos::complete::detail {
namespace {

// The tolerances the proof widens each range by, as multiples of the input's: the conditions
// are the constraints' fundamental parts, whose violation can exceed the constraint's own (an
// axis's angle read at a point along it), so a pose the evaluator accepts is never excluded.
constexpr double kToleranceFactor = 4.0;
// The fewest boxes an attempt with a constraint dropped gets.
constexpr int kLeastBudget = 1000;
// Pairs are tried among the first this many constraints (28 pairs at most).
constexpr std::size_t kMostForPairs = 8;

// Whether every alternative is excluded with only the `active` constraints; `used` the union of
// what the proofs used.
bool excludedEverywhere(const std::vector<ConditionSystem>& systems, SourceMask active,
                        const Tolerance& tol, int max_boxes, SourceMask* used, int* boxes,
                        std::string* why, bool* unbounded = nullptr) {
  *used = 0;
  for (const ConditionSystem& s : systems) {
    ExcludeOptions o;
    o.max_boxes = max_boxes;
    o.length_tolerance = kToleranceFactor * tol.length / s.frame.scale;
    o.angle_tolerance = kToleranceFactor * tol.angle;
    const PoseExclusion e = excludeEveryPose(s, active, o);
    *boxes += e.boxes;
    if (!e.proven) {
      if (why) *why = e.why;
      if (unbounded) *unbounded = e.unbounded;
      return false;
    }
    *used |= e.used;
  }
  return true;
}

enum Reading { kPlanesAndAngles, kBoundedPlanesAndAngles, kAnglesOnly };

// The constraints whose conditions, in every alternative, are angles (and plane offsets).
SourceMask readingOnly(const std::vector<ConditionSystem>& systems, Reading reading) {
  SourceMask others = 0, seen = 0;
  for (const ConditionSystem& s : systems)
    for (const auto* list : {&s.equations, &s.inequalities})
      for (const Condition& c : *list) {
        const SourceMask b = sourceBit(c.source);
        seen |= b;
        const bool plane =
            c.kind == ConditionKind::kPointPlane &&
            (reading == kPlanesAndAngles ||
             (reading == kBoundedPlanesAndAngles && std::isfinite(c.lo) && std::isfinite(c.hi)));
        const bool fits = c.kind == ConditionKind::kCosine || plane;
        if (!fits) others |= b;
      }
  return seen & ~others;
}

}  // namespace

ConflictProof proveConflict(const std::vector<ConditionSystem>& systems, std::size_t constraints,
                            const Tolerance& tol, int max_boxes) {
  ConflictProof r;
  const SourceMask all = constraints >= 64 ? ~SourceMask{0} : (SourceMask{1} << constraints) - 1;
  if (systems.empty()) return r;
  SourceMask used = 0;
  bool unbounded = false;
  bool proven =
      excludedEverywhere(systems, all, tol, max_boxes, &used, &r.boxes, &r.why, &unbounded);
  // When they do not bound the position: those that read it only through plane offsets (then
  // only through bounded ones), then those that do not read it at all (a conflict among the
  // angles alone).
  std::vector<SourceMask> tried = {all};
  for (const Reading reading : {kPlanesAndAngles, kBoundedPlanesAndAngles, kAnglesOnly}) {
    const SourceMask active = readingOnly(systems, reading) & all;
    if (proven || !unbounded || active == 0 ||
        std::find(tried.begin(), tried.end(), active) != tried.end())
      continue;
    tried.push_back(active);
    proven = excludedEverywhere(systems, active, tol, max_boxes, &used, &r.boxes, nullptr);
  }
  // Then every pair, each with a small budget: two constraints that conflict alone may be
  // quick to prove where the whole is not (their angles the only ones, their points bounded).
  const int n = static_cast<int>(std::min<std::size_t>(constraints, kMostForPairs));
  for (int i = 0; i < n && !proven; ++i)
    for (int j = i + 1; j < n && !proven; ++j) {
      const SourceMask pair = (SourceMask{1} << i) | (SourceMask{1} << j);
      proven = excludedEverywhere(systems, pair, tol, std::min(max_boxes, kLeastBudget), &used,
                                  &r.boxes, nullptr);
    }
  if (!proven) return r;
  r.proven = true;
  // The deletion filter: a constraint stays only when the rest cannot be proven to conflict.
  // Each successful proof may use fewer constraints still.
  // A smaller set that conflicts is rarely much harder to prove than the whole (and one that does
  // not would spend the whole budget): each attempt gets a few times what the first took.
  const int budget = std::min(max_boxes, std::max(kLeastBudget, 4 * r.boxes));
  SourceMask kept = used;
  for (int i = 0; i < 64; ++i) {
    const SourceMask b = SourceMask{1} << i;
    if (!(kept & b)) continue;
    SourceMask fewer = 0;
    if (excludedEverywhere(systems, kept & ~b, tol, budget, &fewer, &r.boxes, nullptr))
      kept = fewer;
  }
  r.conflicts = kept;
  return r;
}

}  // namespace relpos::complete::detail
