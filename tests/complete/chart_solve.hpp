#pragma once
// The charts stage alone (complete::solveSets) as the chart tests run it: with the tolerance
// relpos gives the problem's length scale (twice it, as both objects' features count).
#include "relpos/complete/stage.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {

inline Tolerance toleranceOf(const Problem& p) {
  return Tolerance::forScale(2.0 * p.lengthScale());
}

inline Solution solveByCharts(const Problem& p) {
  Solution s;
  s.status = Status::kUnhandled;
  complete::solveSets(p, builtinRegistry(), toleranceOf(p), s);
  return s;
}

}  // namespace relpos::test
