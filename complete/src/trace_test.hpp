#pragma once
// A trace test for a start system's root count (Leykin, Rodriguez & Sottile, "Trace test",
// Arnold Math. J. 2018), run by the generator of the stored start systems (it costs seconds).
//
// S: the affine subspace of parameter space through the start member p0 spanned by the
// parameters the coefficients are jointly affine in (for the encodings: the values, the chart,
// plane normals). Over S the incidence {(x, p) : F(x; p) = 0} is, for each x, an affine-linear
// set of p; so its main component V1 (the closure of the points where those linear conditions
// have full rank) is an affine bundle over the variety X of the equations with no parameter of S
// (the Study quadric e·g = 0 for a pose family, {w·w = 1, q·w = 0} for a line family, all of
// C^n for a family whose every equation has one) and irreducible when X is. The seed root and
// everything monodromy reaches from it lie on V1. Over a general line L of S (random, not through
// p0) the curve C1 = V1 ∩ π⁻¹(L) is irreducible (Bertini: dim S ≥ 2). In (x, t) space, t the
// coordinate on L, a general hyperplane H meets C1 in deg C1 points W; the trace test: W is
// complete iff the sum of the points of W, moved along the parallel pencil H + s, is affine in s
// (a proper subset of the witness set of an irreducible curve is never affine in s). Then every
// isolated point of C1 over a point of L is an endpoint of a path from W as H moves to the fibre
// hyperplane {t = 0} (the points of H at infinity go to infinity): the fibre of V1 is counted.
//
// What it proves is conditional on correct path tracking (the paths are not certified) and on X
// irreducible (true for the encodings' X: a nondegenerate quadric cone; the unit sphere times a
// plane bundle). Roots off V1 (a pose with e·e = 0, never real) are outside its scope; they are
// counted by the total-degree homotopy when it runs. The coefficients along L must be affine in
// t: monomials in (x, t) then have degree one more than in x, at most kMaxMonomialDegree (a
// point-line distance's quartic is not: no trace test there).
#include <cstdint>
#include <string>

#include "relpos/complete/fiber.hpp"

namespace relpos::complete::detail {

struct TraceOutcome {
  bool passed = false;
  std::string why;            // when not passed
  int affine_parameters = 0;  // dim S
  int witness_points = 0;     // deg C1 (the witness set's size when the trace was affine)
  int fibre_roots = 0;        // distinct certified points of V1's fibre recovered from W
  int loops = 0;              // monodromy loops filling W (the last attempt's)
  int attempts = 0;           // attempts run (each its own line, slices and loops)
  double trace_residual = 0;  // relative departure of the trace from an affine function
};

// Checks that s's roots are all of V1's fibre at s.params (moved to a general member of S):
// passed iff the trace test holds and the fibre recovered from the witness set is exactly the
// moved roots.
TraceOutcome traceTest(const Family& f, const StartSystem& s, std::uint64_t seed);

}  // namespace relpos::complete::detail
