#include "relpos/core/problem.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

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

namespace {

// The feature `name` of `o`, or a cylinder's axis for "C.axis" (docs/spec.md §1.6); throws
// std::invalid_argument naming what is missing.
Feature namedFeature(const ObjectSpec& o, const std::string& name, const char* role) {
  if (const Feature* f = o.find(name)) return *f;
  const std::string axis = ".axis";
  if (name.size() > axis.size() && name.compare(name.size() - axis.size(), axis.size(), axis) == 0)
    if (const Feature* c = o.find(name.substr(0, name.size() - axis.size()));
        c && c->kind == FeatureKind::kCylinder)
      return c->axis();
  throw std::invalid_argument("no feature '" + name + "' on the " + role + " object");
}

}  // namespace

Problem& Problem::addConstraint(const std::string& type, const std::string& fixed_feature,
                                const std::string& mobile_feature, double value,
                                Orientation orientation) {
  return addConstraint(
      ConstraintSpec(type, fixed_feature, mobile_feature).value(value).orientation(orientation));
}

ConstraintSpec::ConstraintSpec(std::string type, std::string fixed_feature,
                               std::string mobile_feature)
    : type_(std::move(type)), fixed_(std::move(fixed_feature)), mobile_(std::move(mobile_feature)) {}

ConstraintSpec& ConstraintSpec::value(double v) {
  has_value_ = true;
  value_ = v;
  return *this;
}
ConstraintSpec& ConstraintSpec::range(double min, double max) {
  has_range_ = true;
  min_ = min;
  max_ = max;
  return *this;
}
ConstraintSpec& ConstraintSpec::atLeast(double min) {  // the other bound as it was: both chain
  has_range_ = true;
  min_ = min;
  return *this;
}
ConstraintSpec& ConstraintSpec::atMost(double max) {
  has_range_ = true;
  max_ = max;
  return *this;
}
ConstraintSpec& ConstraintSpec::orientation(Orientation o) {
  orientation_ = o;
  return *this;
}
ConstraintSpec& ConstraintSpec::parallel(bool p) {
  parallel_ = p;
  return *this;
}
ConstraintSpec& ConstraintSpec::id(std::string id) {
  id_ = std::move(id);
  return *this;
}

Problem& Problem::addConstraint(const ConstraintSpec& s) {
  const std::string who = s.id_.empty() ? "constraint '" + s.type_ + "'"
                                        : "constraint '" + s.id_ + "' (" + s.type_ + ")";
  if (s.has_value_ && s.has_range_)
    throw std::invalid_argument(who + ": give either a value or a range, not both");
  if (s.has_value_ && !std::isfinite(s.value_))
    throw std::invalid_argument(who + ": the value is not a finite number");
  if (std::isnan(s.min_) || std::isnan(s.max_))
    throw std::invalid_argument(who + ": a bound is not a number");
  if (s.min_ > s.max_)
    throw std::invalid_argument(who + ": min " + std::to_string(s.min_) +
                                " is greater than max " + std::to_string(s.max_));
  InputConstraint c;
  c.type = s.type_;
  c.id = s.id_;
  c.fixed = namedFeature(fixed, s.fixed_, "fixed");
  c.mobile = namedFeature(mobile, s.mobile_, "mobile");
  c.fixed_name = s.fixed_;
  c.mobile_name = s.mobile_;
  // A range whose ends meet is the exact value (docs/spec.md §1.8), as the reader makes it.
  const bool exact = !s.has_range_ || s.min_ == s.max_;
  c.has_value = exact;
  c.value = s.has_value_ ? s.value_ : (s.has_range_ && exact ? s.min_ : 0.0);
  if (exact && !std::isfinite(c.value))
    throw std::invalid_argument(who + ": the value is not a finite number");
  c.min = exact ? c.value : s.min_;
  c.max = exact ? c.value : s.max_;
  c.orientation = s.orientation_;
  c.parallel = s.parallel_;
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
