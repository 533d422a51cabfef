#pragma once
// Features of an object, in that object's own frame (docs/spec.md §1). Directions are unit after
// parsing. The four kinds are fixed by the spec format, so they are a closed enum.
#include <string>

#include "relpos/core/geometry.hpp"

namespace relpos {

enum class FeatureKind : unsigned char { kPoint, kLine, kPlane, kCylinder };

const char* toString(FeatureKind kind);

struct Feature {
  FeatureKind kind = FeatureKind::kPoint;
  Vector3d point = Vector3d::Zero();       // the point, or a support point of line/plane/axis
  Vector3d direction = Vector3d::UnitZ();  // line/axis direction or plane normal (unit)
  double radius = 0.0;                     // cylinders only

  static Feature makePoint(const Vector3d& p);
  static Feature makeLine(const Vector3d& p, const Vector3d& d);
  static Feature makePlane(const Vector3d& p, const Vector3d& n);
  static Feature makeCylinder(const Vector3d& p, const Vector3d& d, double r);

  // The same feature expressed in the frame in which X places its owner.
  Feature placed(const Isometry3d& X) const;
  // The axis of a cylinder as a line.
  Feature axis() const { return makeLine(point, direction); }
};

}  // namespace relpos
