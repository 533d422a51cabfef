#pragma once
// Up to three planes (PPl, exact or ranged; a point on a line counts as two planes, a pinned
// point as three) with independent normals: a point, a line, a plane, a segment, a strip, an
// infinite or finite parallelepiped (Somani 004 Fig. 3 and Table VI). DOF = free directions +
// ranged planes.
#include "relpos/core/fixed_vector.hpp"
#include "relpos/manifolds/translation/shape.hpp"

namespace relpos::manifolds::translation {

// The planes for a given R: each row n·T = h0 + sign·v (v the row's range parameter for a ranged
// plane, 0 otherwise), with what the projection reads off them besides.
struct PlaneRows {
  int k = 0;
  Vector3d n[3];
  double h0[3] = {0, 0, 0};
  double sign[3] = {1, 1, 1};
  int ranged[3] = {-1, -1, -1};     // index of the row's range parameter among the ranged planes
  Vector3d e1 = Vector3d::UnitX();  // in-plane direction of the first plane (for k = 1)
  Vector3d free[2];                 // the directions along every plane (3 − k of them)
  bool orthogonal = false;          // mutually orthogonal normals: the heights clamp one by one
};

struct Planes : ShapeBase<Planes> {
  static constexpr const char* kName = "Planes";
  static constexpr const char* kSummary =
      "0-3 DOF: up to three planes with independent normals, each exact or a range (a point on a "
      "line counting as two, a pinned point as three): segment, strip, parallelepiped";
  Planes() = default;
  explicit Planes(const FixedVector<Fundamental, 3>& l) : linear(l) { plan(); }
  // The point-plane / point-line / point-point ones. Changed only through the constructor and
  // translate(), which lay out the rows again.
  FixedVector<Fundamental, 3> linear;
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
  void translate(const Vector3d& offset_W, const Vector3d& offset_M) {
    ShapeBase<Planes>::translate(offset_W, offset_M);
    plan();
  }

 private:
  Vector3d projectOntoPlanes(const Matrix3d& R, const Vector3d& T, double* t) const;
  PlaneRows rowsAt(const Matrix3d& R) const;
  void plan();
  // Where every plane and line is the fixed object's (its point the mobile one's, the usual
  // case), the rows' normals do not turn with R: laid out once here, only the heights
  // h0 = n·(q − R p) left to each pose the search weighs (q fixed, p the mobile point).
  bool planned_ = false;
  PlaneRows planned_rows_;
  signed char planned_from_[3] = {0, 0, 0};  // the constraint of `linear` each row comes from
  int planeRows() const;
  int rangedPlanes() const;
};

}  // namespace relpos::manifolds::translation
