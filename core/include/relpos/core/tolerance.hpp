#pragma once
// One tolerance for every rule condition ("parallel", "d_a = 0", "p = q"): never a bare epsilon in
// a rule. Lengths scale with the problem's size so that millimetre and metre specs behave alike.
#include <cmath>

namespace relpos {

struct Tolerance {
  double length = 1e-9;  // absolute length tolerance, already scaled
  double angle = 1e-9;   // radians

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
  bool zeroLength(double v) const { return std::abs(v) <= length; }
  bool equalLength(double a, double b) const { return std::abs(a - b) <= length; }
  bool zeroAngle(double v) const { return std::abs(v) <= angle; }
  bool equalAngle(double a, double b) const { return std::abs(a - b) <= angle; }
  // |sin| of the angle between two unit vectors is below the angle tolerance.
  bool parallelUnit(double cross_norm) const { return cross_norm <= angle; }
};

}  // namespace relpos
