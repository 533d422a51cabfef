#pragma once
// Which constraints conflict (docs/spec.md §8.8): the interval proof that no pose meets them
// (set_exclusion.hpp) over every alternative of the problem, then reduced — each constraint the
// proof used dropped in turn, and kept only when the others alone cannot be proven to conflict —
// to a set none of whose constraints can be dropped (irreducible, as far as the proof can tell).
#include <string>
#include <vector>

#include "pose_conditions.hpp"
#include "relpos/core/fundamental.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos::complete::detail {

struct ConflictProof {
  bool proven = false;
  SourceMask conflicts = 0;  // bit i: input constraint i (mod 64)
  int boxes = 0;             // boxes examined by every proof attempted
  std::string why;           // when not proven
};

// systems: every alternative of the problem (buildConditionSystems).
ConflictProof proveConflict(const std::vector<ConditionSystem>& systems, std::size_t constraints,
                            const Tolerance& tol, int max_boxes);

}  // namespace relpos::complete::detail
