#pragma once
// Interval branch and prune (issue 15's proof of `complete`, docs/spec.md §8.3): that every real
// root of a real square polynomial system inside a bounded box is one of the roots already
// found. The box is covered by boxes each of which is proven either to hold no root or to hold
// exactly one root that is a known one (inside a known root's uniqueness box, or Krawczyk's
// operator inside the box and the known root's enclosure too). A positive-dimensional set of
// real roots, a singular root or a root not found leaves some box undecided: nothing is proven.
//
// Each box is first contracted: every equation projected on the variables it holds alone (x or
// x², e.g. a unit norm), then the "secondary" variables — those the equations hold linearly once
// the others are fixed, a translation given a rotation — by preconditioned interval Gauss-Seidel
// on the equations linear in them (equations with the same quadratic part in them, such as two
// point-point distances, are first subtracted: their difference is linear). Bisection then
// splits the primary variables (a rotation) and a secondary one only while the equations do not
// pin it: the search is as deep as the rotation's dimension, not the pose's.
//
// Outward rounding throughout (rounded_interval.hpp); the coefficients are enclosures of the real
// member's, so the proof holds for the exact system they enclose.
#include <string>
#include <vector>

#include "polynomial_eval.hpp"

namespace relpos::complete::detail {

// A box by its bounds (lo[i] ≤ hi[i]).
struct RealBox {
  RVec lo, hi;
};

struct ExclusionOptions {
  // Boxes examined before giving up.
  int max_boxes = 40000;
  // A box undecided when narrower than this fraction of the domain in every coordinate is
  // given up on (a singular root, a curve of roots).
  double min_width = 1e-10;
};

struct ExclusionResult {
  bool proven = false;  // every real root in the domain is a known one
  int boxes = 0;        // boxes examined
  std::string why;      // when not proven
};

// coefficients: enclosures of the member's coefficients (shape's term order). known: each an
// enclosure of one real root (proven to exist there, e.g. a certified box). secondary: per
// variable, whether it is solved for rather than branched on first (may be empty: none).
// negated: variables whose negation maps every root of every member to a root (a symmetry of
// the system; empty: none). With one, the domain may be half of the space (the other half its
// image), and the proof also requires the image of every known root to be a known root.
ExclusionResult excludeUnknownRoots(const SystemShape& shape, const Interval* coefficients,
                                   const RealBox& domain, const std::vector<RealBox>& known,
                                   const std::vector<bool>& secondary,
                                   const std::vector<int>& negated = {},
                                   const ExclusionOptions& options = ExclusionOptions());

}  // namespace relpos::complete::detail
