#include "relpos/manifolds/translation_part.hpp"

namespace relpos::manifolds {

const char* TranslationPart::name() const {
  return std::visit([](const auto& s) { return s.kName; }, shape);
}
int TranslationPart::dof() const {
  return std::visit([](const auto& s) { return s.dof(); }, shape);
}
Parameter TranslationPart::parameter(int i) const {
  return std::visit([i](const auto& s) { return s.parameter(i); }, shape);
}
Vector3d TranslationPart::translation(const Matrix3d& R, const double* t) const {
  return std::visit([&](const auto& s) { return s.translation(R, t); }, shape);
}
void TranslationPart::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  std::visit([&](const auto& s) { s.project(R, T, t); }, shape);
}
Vector3d TranslationPart::projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const {
  return std::visit([&](const auto& s) { return s.projectAndPlace(R, T, t); }, shape);
}
bool TranslationPart::projectsExactly() const {
  return std::visit([](const auto& s) { return s.projectsExactly(); }, shape);
}
bool TranslationPart::invariantUnderSpin(const Vector3d& u) const {
  return std::visit([&](const auto& s) { return s.invariantUnderSpin(u); }, shape);
}
bool TranslationPart::invariantUnderRotation() const {
  return std::visit([](const auto& s) { return s.invariantUnderRotation(); }, shape);
}
double TranslationPart::rotationCoupling() const {
  return std::visit([](const auto& s) { return s.rotationCoupling(); }, shape);
}
void TranslationPart::translate(const Vector3d& offset_W, const Vector3d& offset_M) {
  std::visit([&](auto& s) { s.translate(offset_W, offset_M); }, shape);
}

}  // namespace relpos::manifolds
