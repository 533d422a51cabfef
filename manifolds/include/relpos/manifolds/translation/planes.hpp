#pragma once
// Up to three planes (PPl, exact or ranged; a point on a line counts as two planes, a pinned
// point as three) with independent normals: a point, a line, a plane, a segment, a strip, an
// infinite or finite parallelepiped (Somani 004 Fig. 3 and Table VI). DOF = free directions +
// ranged planes.
#include "relpos/core/fixed_vector.hpp"
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

struct Planes : ShapeBase<Planes> {
  static constexpr const char* kName = "Planes";
  static constexpr const char* kSummary =
      "0-3 DOF: up to three planes with independent normals, each exact or a range (a point on a "
      "line counting as two, a pinned point as three): segment, strip, parallelepiped";
  Planes() = default;
  explicit Planes(const FixedVector<Fundamental, 3>& l) : linear(l) {}
  FixedVector<Fundamental, 3> linear;  // the point-plane / point-line / point-point ones
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    for (auto& f : self.linear) fn(f);
  }

  int dof() const;
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
  // For plane rows the placement reuses the rows the projection built.
  Vector3d projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const;

 private:
  Vector3d projectOntoPlanes(const Matrix3d& R, const Vector3d& T, double* t) const;
  int planeRows() const;
  int rangedPlanes() const;
};

}  // namespace relpos::manifolds::translation
