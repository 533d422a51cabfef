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

// --- Rounding guards (manifolds/, Manifold::contains) ----------------------------------------
// Not tolerances of the problem: each decides between two formulas that agree where it switches,
// or whether a closed form is exact, at the level of the rounding the formula's inputs carry. A
// user's tolerance must not move them: a spin taken as not moving a feature 1e-9 off its axis
// would give a nearest pose that is not the nearest.
//
// What is left of an exact zero in a quantity computed from unit vectors (a cross product's
// norm, a cosine's distance from ±1): ~4500 ulps of 1. Below it a direction read off the quantity
// is rounding, and a deterministic one is taken instead.
inline constexpr double kUnitRounding = 1e-12;
// A length no direction can be read from (a guard against 0/0; every length of a problem that
// passed the solver's checks is far above it).
inline constexpr double kDivisionGuard = 1e-300;
// An angle read off a cosine near ±1 (acos at a tangency) keeps only the square root of the
// cosine's rounding, ~1.5e-8; a few of those.
inline constexpr double kCosineAngleRounding = 1e-7;
// The smallest angle tolerance a matcher's formula can honour where it divides by 1 ∓ cos α or
// compares rotations built through acos: the solver's default (SolverOptions::angle_tolerance).
// A smaller tolerance asked for is raised to it there (angleAboveRounding), a larger one used.
inline constexpr double kAngleRoundingFloor = 1e-9;

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
  // Whether two directions parallel within the angle tolerance are tilted beyond what rounding
  // makes of parallel ones (a sine |a × b| or |d·n| above kUnitRounding, the rules' threshold
  // since issue 18): such features drift apart along their length, and what a rule reads where
  // the problem is centred is theirs only there (docs/spec.md §6.4). At or below it, parallel.
  static bool tiltedBeyondRounding(double sine) { return std::abs(sine) > kUnitRounding; }
  // The angle tolerance, never below kAngleRoundingFloor: for decisions the formulas' own rounding
  // reaches (which of three angles is degenerate, whether two of up to eight rotations are one).
  double angleAboveRounding() const {
    return angle > kAngleRoundingFloor ? angle : kAngleRoundingFloor;
  }
  // How far a pose's projection, mapped back, may land from it and still be on the manifold
  // (Manifold::contains): the tolerances as far as a construction within kConditioningBound
  // magnifies them (length scaled by the pose's distance from the origin, at least 1), plus for
  // the angle what is left of one read off a cosine near ±1.
  double roundTripLength(double scale) const { return kConditioningBound * length * scale; }
  double roundTripAngle() const { return kConditioningBound * angle + kCosineAngleRounding; }
};

}  // namespace relpos
