#pragma once
// The box that holds every translation meeting a set of slabs lo ≤ n·t ≤ hi — what the interval
// proofs (real_root_proof.cpp, set_exclusion.cpp) search over: the constraints that bound the
// mobile object's position (a distance's upper end, a plane offset's range) bound the search.
#include <vector>

#include "relpos/core/geometry.hpp"

namespace relpos::complete::detail {

// lo ≤ n·t ≤ hi, from constraint `source` (-1: none in particular).
struct Slab {
  Vector3d n;
  double lo, hi;
  int source = -1;
};

enum class Bound { kBox, kUnbounded, kEmpty };

// The box [lo, hi] holding every t that meets all slabs (kEmpty: none does, some coordinate's
// bounds cross), or kUnbounded when some coordinate is not bounded (its bounds infinite, the
// others still set): from every well-conditioned triple t = N⁻¹ s. Widened by far more than the
// rounding of N⁻¹ plus `margin` (a larger domain only costs boxes; an empty one is then a
// proof).
Bound boundingBox(const std::vector<Slab>& slabs, double margin, Vector3d* lo, Vector3d* hi);

// The three axis slabs of a ball.
void ballSlabs(const Vector3d& centre, double radius, std::vector<Slab>* out, int source = -1);

}  // namespace relpos::complete::detail
