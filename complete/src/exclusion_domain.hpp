#pragma once
// The domain the proof of inconsistency searches (set_exclusion.hpp, docs/spec.md §8.8): the
// slabs the conditions give the translation, a world frame that follows their directions, the
// coordinates no condition reads, and the span of the plane normals when only those read it.
#include <vector>

#include "pose_conditions.hpp"
#include "translation_bound.hpp"

namespace relpos::complete::detail {

// The slabs the conditions give the translation t (x = R p + t, |R p| = |p|): a reach's ball, a
// two-sided plane offset's slab, a distance to a line's two slabs across it.
std::vector<Slab> translationSlabs(const std::vector<Condition>& cs);

// A world frame whose axes follow the conditions' fixed directions (planes' normals first, then
// the line between two reaches' centres, lines', angles'): a slab across an axis then bounds one
// coordinate of a box, not a sum of three.
Matrix3d alignedFrame(const std::vector<Condition>& cs);

// Whether no condition reads the translation's coordinate i (exactly: zeros in the data).
bool independentOf(const std::vector<Condition>& cs, int i);

// When every condition reading the translation is a plane offset along at most two normals:
// the translations T τ (τ in [lo, hi]) spanned by them hold every solution's offsets.
// kUnbounded when the conditions are not of that shape; kEmpty when the slabs cross.
Bound planesOnly(const std::vector<Condition>& cs, const std::vector<Slab>& slabs, Matrix3d* T,
                 Vector3d* lo, Vector3d* hi);

}  // namespace relpos::complete::detail
