#include "relpos/core/feature.hpp"

namespace relpos {

const char* toString(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::kPoint:
      return "point";
    case FeatureKind::kLine:
      return "line";
    case FeatureKind::kPlane:
      return "plane";
    case FeatureKind::kCylinder:
      return "cylinder";
  }
  return "?";
}

Feature Feature::makePoint(const Vector3d& p) {
  Feature f;
  f.kind = FeatureKind::kPoint;
  f.point = p;
  return f;
}
Feature Feature::makeLine(const Vector3d& p, const Vector3d& d) {
  Feature f;
  f.kind = FeatureKind::kLine;
  f.point = p;
  f.direction = d.normalized();
  return f;
}
Feature Feature::makePlane(const Vector3d& p, const Vector3d& n) {
  Feature f = makeLine(p, n);
  f.kind = FeatureKind::kPlane;
  return f;
}
Feature Feature::makeCylinder(const Vector3d& p, const Vector3d& d, double r) {
  Feature f = makeLine(p, d);
  f.kind = FeatureKind::kCylinder;
  f.radius = r;
  return f;
}

Feature Feature::placed(const Isometry3d& X) const {
  Feature f = *this;
  f.point = X * point;
  f.direction = X.linear() * direction;
  return f;
}

}  // namespace relpos
