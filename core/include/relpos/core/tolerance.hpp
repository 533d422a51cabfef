#pragma once
// One tolerance for every rule condition ("parallel", "d_a = 0", "p = q"): never a bare epsilon in
// a rule. Lengths scale with the problem's size so that millimetre and metre specs behave alike.
#include <cmath>
#include <limits>

namespace relpos {

// The first combination round's bound on Tolerance::max_amplification (centring.cpp
// toleranceFor). Rules that refuse, rather than defer, an output whose inputs already carry an
// uncertainty (Fundamental::err) refuse it beyond this gain in every round.
inline constexpr double kConditioningBound = 1e3;
// The rounding a given vector or value carries relative to the problem as meant (half an ulp per
// coordinate, a few more from placing features by a pose and normalising): what an
// ill-conditioned construction magnifies even when no rule derived its inputs (err = 0).
inline constexpr double kInputRounding = 16 * 2.220446049250313e-16;
static_assert(kInputRounding == 16 * std::numeric_limits<double>::epsilon());

// How far outside its range ([0, π], or [−π/2, π/2] for a line and a plane) a given angle may be
// and still be read as in it: the rounding of a value converted from degrees (180° is an ulp or
// so beyond π) with room to spare. A check of the input, not a tolerance of the solve.
inline constexpr double kAngleRangeSlack = 1e-12;

// The largest uncertainty (Fundamental::err, radians) a derived angle constraint may carry. Rules
// and matchers widen their comparisons by it, a first-order allowance that holds while it is small
// beside the problem's angles; the direction of a span 1e-12 long known to 4e-14 (err 0.17) would
// take vectors 60° apart for one. Near-tangent readings (the square root of the tolerance, ~5e-5)
// stay below it, and so do chains of two (cones meeting near a tangency, then a parallelism
// meeting that direction's cone near one: ~2e-3 for a task placed 1e6 away: a cap of 1e-3 left
// it unhandled there while solving it at the origin).
inline constexpr double kMaxDerivedErr = 1e-2;

struct Tolerance {
  double length = 1e-9;  // absolute length tolerance, already scaled
  double angle = 1e-9;   // radians
  // How much a rule may magnify the coordinates' rounding in what it builds (a point where lines
  // 1e-8 rad apart cross is uncertain along them by rounding / 1e-8). The solver first combines
  // with a bound, so that a well-conditioned pair decides before an ill-conditioned one whose
  // output would be off by more than a third constraint's tolerance, then with the bound rounding
  // allows (solver.cpp, combineInRounds).
  double max_amplification = 1e300;
  // Whether a rule building something `amplification` times as uncertain as its inputs should
  // wait (RuleOutput::defer) for the pairs that can decide it better.
  bool tooIllConditioned(double amplification) const {
    return !(amplification <= max_amplification);
  }

  // For code that combines constraint sets itself (the rule and plugin test kits). The solver
  // measures the problem's own size instead (core/src/centring.hpp).
  static Tolerance forScale(double scale, double relative_length = 1e-9, double angle = 1e-9) {
    Tolerance t;
    t.length = relative_length * (scale > 1.0 ? scale : 1.0);
    t.angle = angle;
    return t;
  }
  // The same tolerance with `extra_angle` radians (the uncertainty of derived vectors) added.
  Tolerance widened(double extra_angle) const {
    Tolerance t = *this;
    t.angle += extra_angle;
    return t;
  }
  // The same with `extra_length` (the uncertainty of derived points and lines) added.
  Tolerance widenedLength(double extra_length) const {
    Tolerance t = *this;
    t.length += extra_length;
    return t;
  }
  bool zeroLength(double v) const { return std::abs(v) <= length; }
  bool equalLength(double a, double b) const { return std::abs(a - b) <= length; }
  bool zeroAngle(double v) const { return std::abs(v) <= angle; }
  bool equalAngle(double a, double b) const { return std::abs(a - b) <= angle; }
  // |sin| of the angle between two unit vectors is below the angle tolerance.
  bool parallelUnit(double cross_norm) const { return cross_norm <= angle; }
  // Whether a sine (|a × b|, |d·n|) is more than the inputs' rounding (kInputRounding): below it
  // two directions are parallel for every purpose, whatever the tolerance (a crossing so far away
  // is only rounding's).
  static bool beyondRounding(double sine) { return std::abs(sine) > kInputRounding; }
};

}  // namespace relpos
