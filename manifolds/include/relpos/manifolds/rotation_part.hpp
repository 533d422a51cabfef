#pragma once
// The rotational component of a separable solution (PMF Table III, App. III): one of the shapes
// of RotationShape (rotation/shapes.hpp), each in its own file, called through std::visit.
#include <utility>
#include <variant>

#include "relpos/core/geometry.hpp"
#include "relpos/core/manifold.hpp"
#include "relpos/manifolds/rotation/shapes.hpp"

namespace relpos::manifolds {

struct RotationPart {
  RotationShape shape;

  RotationPart() : shape(rotation::Free{}) {}
  template <typename Shape,
            typename = std::enable_if_t<std::is_constructible_v<RotationShape, Shape>>>
  RotationPart(Shape s) : shape(std::move(s)) {}  // NOLINT(google-explicit-constructor)

  const char* name() const;
  int dof() const;
  Parameter parameter(int i) const;
  Matrix3d rotation(const double* theta) const;
  void project(const Matrix3d& R, double* theta) const;
  // See rotation::ShapeBase.
  Matrix3d baseRotation() const;
  const Vector3d* spinAxis() const;
  int spinIndex() const;
  Matrix3d spinBase(const double* theta) const;
  bool projectsExactly() const;

  template <typename Shape>
  const Shape* as() const {
    return std::get_if<Shape>(&shape);
  }
  template <typename Shape>
  bool is() const {
    return std::holds_alternative<Shape>(shape);
  }
};

}  // namespace relpos::manifolds
