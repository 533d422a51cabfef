#include "relpos/core/problem.hpp"

#include <algorithm>
#include <stdexcept>

namespace relpos {

const char* toString(Orientation o) {
  switch (o) {
    case Orientation::kAligned:
      return "aligned";
    case Orientation::kOpposed:
      return "opposed";
    case Orientation::kEither:
      return "either";
  }
  return "?";
}

const Feature* ObjectSpec::find(const std::string& feature_name) const {
  for (const auto& f : features)
    if (f.name == feature_name) return &f.feature;
  return nullptr;
}

Problem& Problem::addFixedFeature(const std::string& n, const Feature& f) {
  fixed.features.push_back({n, f});
  return *this;
}
Problem& Problem::addMobileFeature(const std::string& n, const Feature& f) {
  mobile.features.push_back({n, f});
  return *this;
}

Problem& Problem::addConstraint(const std::string& type, const std::string& fixed_feature,
                                const std::string& mobile_feature, double value,
                                Orientation orientation) {
  const Feature* f = fixed.find(fixed_feature);
  const Feature* m = mobile.find(mobile_feature);
  if (!f) throw std::invalid_argument("no feature '" + fixed_feature + "' on the fixed object");
  if (!m) throw std::invalid_argument("no feature '" + mobile_feature + "' on the mobile object");
  InputConstraint c;
  c.type = type;
  c.fixed = *f;
  c.mobile = *m;
  c.fixed_name = fixed_feature;
  c.mobile_name = mobile_feature;
  c.has_value = true;
  c.value = value;
  c.min = c.max = value;
  c.orientation = orientation;
  constraints.push_back(c);
  return *this;
}

double Problem::lengthScale() const {
  double s = 0.0;
  auto grow = [&s](const Vector3d& v) { s = std::max(s, v.cwiseAbs().maxCoeff()); };
  for (const ObjectSpec* o : {&fixed, &mobile}) {
    grow(o->pose.translation());
    for (const auto& f : o->features) {
      grow(f.feature.point);
      s = std::max(s, f.feature.radius);
    }
  }
  for (const auto& c : constraints) {
    if (c.has_value) s = std::max(s, std::abs(c.value));
  }
  return s;
}

}  // namespace relpos
