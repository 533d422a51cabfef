#pragma once
// A plane: a point on a plane (PPl, PMF Table V).
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Plane : ShapeBase<Plane> {
  static constexpr const char* kName = "Plane";
  static constexpr const char* kSummary = "2 DOF: point on a plane";
  explicit Plane(const Fundamental& f) : c(f) {}
  Fundamental c;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.c);
  }

  int dof() const { return 2; }
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
};

}  // namespace relpos::manifolds::translation
