#pragma once
// A line: a point on two planes that are not parallel (PPl ∩ PPl, PMF §V-B.5); the line is
// recomputed for each R.
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct LineOfPlanes : ShapeBase<LineOfPlanes> {
  static constexpr const char* kName = "Line";
  static constexpr const char* kSummary =
      "1 DOF: point on two planes (their line recomputed for each rotation)";
  LineOfPlanes(const Fundamental& a, const Fundamental& b) : first(a), second(b) {}
  Fundamental first, second;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.first);
    fn(self.second);
  }

  int dof() const { return 1; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
