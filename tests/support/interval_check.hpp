#pragma once
// An independent interval check of a certified pose (issue 15): given a reported pose and a box
// radius, prove with Boost.Interval that a solution exists in the box — Krawczyk's test in local
// exponential coordinates about the pose (rotation R = exp([ω]×) R0, translation t0 + δt), the
// unknowns the constraints' residuals, written here from docs/spec.md §1.9 as polynomial equations
// (squared distances, cosines), not from relpos's encoding. K(X) inside the box's interior proves
// exactly one solution of the equations in the box (Krawczyk 1969, Moore's uniqueness theorem).
#include <string>

#include "relpos/core/problem.hpp"

namespace relpos::test {

struct IntervalBox {
  double radius = 0.0;  // half-width of every translation coordinate (the problem's units)
  double angle = 0.0;   // half-width of every rotation-vector coordinate (radians)
  // The mobile features all lie on one line (four spheres): spin about it and slide along it are
  // free, so the unknowns are the two rotation and two translation coordinates across the line.
  bool line_quotient = false;
};

struct IntervalVerdict {
  bool proven = false;
  std::string why;  // what failed: an unsupported constraint, a singular Jacobian, K(X) outside
};

// The box a relpos certificate {radius, angle} (docs/spec.md §2) describes: each translation
// coordinate within ±radius, the rotation within `angle` (each rotation-vector coordinate within
// angle/√3, so that the whole vector is). An angle of 0 with a positive radius is read as
// radius / 3, the radius over the benchmark problems' size.
IntervalBox certificateBox(double radius, double angle, bool line_quotient);

IntervalVerdict provesSolutionInBox(const Problem& p, const Isometry3d& X_WM,
                                    const IntervalBox& box);

// A solution within `box` of X_WM: Krawczyk on the box, then on boxes shrunk by 10 at a time
// (down to 1e-12 of it), since a root proven in a smaller box is within the larger one too and
// Krawczyk's test can fail on a box wider than the Jacobian's variation allows. `why` of the
// verdict is the first box's.
IntervalVerdict provesSolutionWithin(const Problem& p, const Isometry3d& X_WM, IntervalBox box);

}  // namespace relpos::test
