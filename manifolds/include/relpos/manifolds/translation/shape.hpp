#pragma once
// What every translation shape of a separable branch provides (PMF Tables IV and V, Somani 004
// Table VI). Given the rotation R, every translational fundamental constraint confines T to a
// primitive shape in translation space (T = S_f − R S_m, PMF eq. 6); a translation shape is one
// such shape, the intersection of two whose directions keep their relative orientation for every
// R, or the thick version of one. Each is a small value type in its own header and source, held
// in TranslationShape (shapes.hpp) and called through std::visit: no virtual call per
// evaluation, no heap. A shape has
//   static constexpr const char* kName;     // written in results ("..., translation Planes")
//   static constexpr const char* kSummary;  // the registry's catalogue entry
//   template <typename Self, typename Fn> static void eachConstraint(Self& self, Fn fn);
//   int dof() const;
//   Parameter parameter(int i) const;
//   Vector3d translation(const Matrix3d& R, const double* t) const;
//   void project(const Matrix3d& R, const Vector3d& T, double* t) const;
// and may replace the defaults of ShapeBase below.
#include <limits>

#include "relpos/core/fundamental.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::manifolds {

// A shape in translation space for a given R.
struct TShape {
  enum Kind : unsigned char { kPoint, kLine, kPlane, kSphere, kCylinder } kind = kPoint;
  Vector3d c = Vector3d::Zero();    // centre / support point
  Vector3d d = Vector3d::UnitZ();   // line or axis direction, or plane normal
  Vector3d e1 = Vector3d::UnitX();  // a unit vector ⊥ d that turns with d's owner
  double r = 0.0;
};
TShape shapeOf(const Fundamental& f, const Matrix3d& R);

// The plane of a point-plane constraint in translation space (shapeOf's c and d without its
// in-plane direction, which costs a perpendicular and is not needed where this is used: the
// nearest-pose search evaluates these for every pose it tries).
void planeOf(const Fundamental& f, const Matrix3d& R, Vector3d* c, Vector3d* n);

// Where the line (c, d) meets a plane shape (not parallel to it).
Vector3d whereLineMeetsPlane(const Vector3d& c, const Vector3d& d, const TShape& plane);

// Whether constraint f confines T the same way for R and R·R(u, θ) (every θ): its mobile point on
// the line through the mobile origin along u, its mobile line along it, its mobile plane normal
// to it.
bool mobileGeometryInvariant(const Fundamental& f, const Vector3d& u);

// Whether constraint f confines T the same way for every R: a point-based constraint whose
// mobile point is the mobile origin, exactly (T = S_f − R·0; a point off it by any amount moves
// T with R, and the branch's nearest pose would no longer be its projection).
bool mobilePointAtOrigin(const Fundamental& f);

// The mobile point of a point-based constraint whose point is the mobile side's (its positions
// for R are S_f − R·p, S_f fixed), else null.
const Vector3d* mobileConstraintPoint(const Fundamental& f);

namespace translation {

template <typename Derived>
struct ShapeBase {
  // Whether project() gives the translation nearest T (for every R).
  bool projectsExactly() const { return true; }
  // project(), then translation(R, t): the nearest-pose search does both per evaluation (a shape
  // may share the work between them).
  Vector3d projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const {
    self().project(R, T, t);
    return self().translation(R, t);
  }
  // Whether the translation set, for given parameters, is the same for R and R·R(u, θ) (every θ):
  // the spin about u then moves only the rotation.
  bool invariantUnderSpin(const Vector3d& u) const {
    bool all = true;
    Derived::eachConstraint(
        self(), [&](const Fundamental& f) { all = all && mobileGeometryInvariant(f, u); });
    return all;
  }
  // Whether the translation set, for given parameters, is the same for every R: each constraint's
  // mobile point is the mobile origin.
  bool invariantUnderRotation() const {
    bool all = true;
    Derived::eachConstraint(self(),
                            [&](const Fundamental& f) { all = all && mobilePointAtOrigin(f); });
    return all;
  }
  // How far the distance from a position to the translation set moves, at most, per radian the
  // rotation turns: |p| when every constraint holds the same mobile point p (the set for R is
  // S − R·p, and R·p moves no farther than |p| a radian; a distance to a set moves no farther
  // than the set), 0 without constraints, +inf otherwise (a mobile line or plane turns the set
  // about a point that may lie anywhere).
  double rotationCoupling() const {
    const Vector3d* p = nullptr;
    bool one_point = true;
    Derived::eachConstraint(self(), [&](const Fundamental& f) {
      const Vector3d* q = mobileConstraintPoint(f);
      one_point = one_point && q && (!p || *q == *p);
      if (q && !p) p = q;
    });
    if (!one_point) return std::numeric_limits<double>::infinity();
    return p ? p->norm() : 0.0;
  }
  // Every constraint's fixed point moved by offset_W, its mobile point by offset_M.
  void translate(const Vector3d& offset_W, const Vector3d& offset_M) {
    Derived::eachConstraint(static_cast<Derived&>(*this),
                            [&](Fundamental& f) { f.translate(offset_W, offset_M); });
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

// The parameters the shapes share: a length along a line or plane, an azimuth, a polar angle, a
// constraint's own value within its range.
Parameter lengthParameter(const char* name);
Parameter azimuthParameter();
Parameter polarParameter();
Parameter rangeParameter(const Fundamental& f);
inline double clampToRange(const Fundamental& f, double v) {
  return v < f.lo ? f.lo : (v > f.hi ? f.hi : v);
}

// A shape defined by one constraint (most of them): holds it and visits it.
template <typename Derived>
struct OneConstraintShape : ShapeBase<Derived> {
  explicit OneConstraintShape(const Fundamental& f) : c(f) {}
  Fundamental c;
  template <typename Self, typename Fn>
  static void eachConstraint(Self& self, Fn fn) {
    fn(self.c);
  }
};

}  // namespace translation
}  // namespace relpos::manifolds
