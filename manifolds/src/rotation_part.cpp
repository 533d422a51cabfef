#include "relpos/manifolds/rotation_part.hpp"

namespace relpos::manifolds {

const char* RotationPart::name() const {
  return std::visit([](const auto& s) { return s.kName; }, shape);
}
int RotationPart::dof() const {
  return std::visit([](const auto& s) { return s.dof(); }, shape);
}
Parameter RotationPart::parameter(int i) const {
  return std::visit([i](const auto& s) { return s.parameter(i); }, shape);
}
Matrix3d RotationPart::rotation(const double* theta) const {
  return std::visit([theta](const auto& s) { return s.rotation(theta); }, shape);
}
void RotationPart::project(const Matrix3d& R, double* theta) const {
  std::visit([&](const auto& s) { s.project(R, theta); }, shape);
}
Matrix3d RotationPart::baseRotation() const {
  return std::visit([](const auto& s) { return s.baseRotation(); }, shape);
}
const Vector3d* RotationPart::spinAxis() const {
  return std::visit([](const auto& s) { return s.spinAxis(); }, shape);
}
int RotationPart::spinIndex() const {
  return std::visit([](const auto& s) { return s.spinIndex(); }, shape);
}
Matrix3d RotationPart::spinBase(const double* theta) const {
  return std::visit([theta](const auto& s) { return s.spinBase(theta); }, shape);
}
bool RotationPart::projectsExactly() const {
  return std::visit([](const auto& s) { return s.projectsExactly(); }, shape);
}

}  // namespace relpos::manifolds
