#pragma once
// The translational component of a separable solution (PMF Tables IV and V, Somani 004 Table VI):
// one of the shapes of TranslationShape (translation/shapes.hpp), each in its own file, called
// through std::visit. See translation/shape.hpp for what each provides.
#include <utility>
#include <variant>

#include "relpos/manifolds/translation/shapes.hpp"

namespace relpos::manifolds {

struct TranslationPart {
  TranslationShape shape;

  TranslationPart() : shape(translation::Free{}) {}
  template <typename Shape,
            typename = std::enable_if_t<std::is_constructible_v<TranslationShape, Shape>>>
  TranslationPart(Shape s) : shape(std::move(s)) {}  // NOLINT(google-explicit-constructor)

  const char* name() const;
  int dof() const;
  Parameter parameter(int i) const;
  Vector3d translation(const Matrix3d& R, const double* t) const;
  void project(const Matrix3d& R, const Vector3d& T, double* t) const;
  Vector3d projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const;
  bool projectsExactly() const;
  bool invariantUnderSpin(const Vector3d& u) const;
  bool invariantUnderRotation() const;
  double rotationCoupling() const;
  void translate(const Vector3d& offset_W, const Vector3d& offset_M);

  template <typename Shape>
  const Shape* as() const {
    return std::get_if<Shape>(&shape);
  }
};

}  // namespace relpos::manifolds
