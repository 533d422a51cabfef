#pragma once
// Translational components of separable solutions (PMF Tables IV and V). Given the rotation R,
// every translational fundamental constraint confines T to a primitive shape in translation space
// (point, line, plane, sphere or cylinder: T = S_f - R S_m, PMF eq. 6); a translation part is one
// such shape or the intersection of two whose directions keep their relative orientation for
// every R (plane∩plane → line, line∩plane → point, cylinder∩plane → ellipse/circle).
#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds {

enum class TranslationKind : unsigned char {
  kFree,              // R³                       3 DOF
  kPoint,             // PP0                      0
  kLine,              // PL0                      1
  kPlane,             // PPl                      2
  kSphere,            // PP p > 0                 2
  kCylinder,          // PL p > 0                 2
  kLineOfPlanes,      // PPl ∩ PPl (non-parallel) 1 (line recomputed for each R, PMF §V-B.5)
  kPointOfLinePlane,  // PL0 ∩ PPl (non-parallel) 0
  kEllipse,           // PL p ∩ PPl (non-parallel) 1 (PMF eq. 10)
  // Ranges (Somani 004 Table VI): the distance itself is a bounded parameter.
  kShell,          // PP in [lo, hi]            3 (a thick sphere)
  kThickCylinder,  // PL in [lo, hi]            3
  kSlab,           // PPl in [lo, hi] (signed)  3 (Somani's infinite Box)
  // Up to three planes (PPl, exact or ranged; a point on a line counts as two planes, a pinned
  // point as three) with independent normals: a point, a line, a plane, a segment, a strip, an
  // infinite or finite parallelepiped (Somani 004 Fig. 3 and Table VI). DOF = free directions +
  // ranged planes.
  kPlanes,
  // A point-line distance (exact or ranged) with a point-plane constraint (exact or ranged) on a
  // plane the line crosses: an annulus, a finite cylinder or a finite thick cylinder, square or
  // oblique (Somani's grasp volumes, oblique cylinder). DOF = 1 (azimuth) + ranged constraints.
  kBoundedCylinder,
};
const char* toString(TranslationKind k);

// A shape in translation space for a given R.
struct TShape {
  enum Kind : unsigned char { kPoint, kLine, kPlane, kSphere, kCylinder } kind = kPoint;
  Vector3d c = Vector3d::Zero();    // centre / support point
  Vector3d d = Vector3d::UnitZ();   // line or axis direction, or plane normal
  Vector3d e1 = Vector3d::UnitX();  // a unit vector ⊥ d that turns with d's owner
  double r = 0.0;
};
TShape shapeOf(const Fundamental& f, const Matrix3d& R);

struct TranslationPart {
  TranslationKind kind = TranslationKind::kFree;
  Fundamental c1, c2;
  FixedVector<Fundamental, 3> linear;  // kPlanes: the point-plane / point-line / point-point ones

  int dof() const;
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
  // project(), then translation(R, t): the nearest-pose search does both per evaluation, and for
  // plane rows the second reuses the rows the first built.
  Vector3d projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const;
  // Whether project() gives the translation nearest T (for every R): not for an ellipse (its
  // parameter is affine, not the foot point) nor for a finite cylinder cut obliquely (its radius
  // and height are clamped along directions that are not orthogonal).
  bool projectsExactly() const;
  // Whether the translation set, for given parameters, is the same for R and R·R(u, θ) (every θ):
  // every mobile point on the line through the mobile origin along u, every mobile line along
  // it, every mobile plane normal to it. The spin about u then moves only the rotation.
  bool invariantUnderSpin(const Vector3d& u) const;
  // Every constraint's fixed point moved by offset_W, its mobile point by offset_M.
  void translate(const Vector3d& offset_W, const Vector3d& offset_M);

 private:
  Parameter rangeParameter() const;
  Vector3d projectOntoPlanes(const Matrix3d& R, const Vector3d& T, double* t) const;
  double clampRange(double v) const { return v < c1.lo ? c1.lo : (v > c1.hi ? c1.hi : v); }
  // T = S_f − R S_m: a mobile point on a fixed plane moves with +n, a fixed point on a mobile
  // plane puts T on the −n side.
  double slabSign() const { return c1.point_side == Side::kMobile ? 1.0 : -1.0; }
  int planeRows() const;
  int rangedPlanes() const;
};

}  // namespace relpos::manifolds
