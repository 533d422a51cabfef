#pragma once
// The immutable description of a relational positioning problem, as parsed from a spec or built
// in code. Nothing here is solved yet.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "relpos/core/feature.hpp"

namespace relpos {

enum class Orientation : unsigned char { kAligned, kOpposed, kEither };
const char* toString(Orientation o);

struct NamedFeature {
  std::string name;  // as referenced in constraints ("K", or "cyl.axis")
  Feature feature;
};

struct ObjectSpec {
  std::string name;
  Isometry3d pose = Isometry3d::Identity();  // fixed: X_WF; mobile: initial X_WM
  std::vector<NamedFeature> features;
  std::string mesh;  // optional, relative to the spec file
  double mesh_scale = 1.0;  // the mesh's coordinates times this (> 0): its units into the spec's
  // Collision filtering (docs/spec.md §5.2, since issue 17): the mobile object must keep this far
  // from this object (≥ 0), instead of the command's --clearance; negative: the command's.
  double clearance = -1.0;
  const Feature* find(const std::string& feature_name) const;
};

// One input constraint (docs/spec.md §1 "Constraints"). Angles are in radians after parsing.
struct InputConstraint {
  std::string type;  // "distance", "angle", "coincident", ... (registry name)
  std::string id;    // optional user id, echoed in diagnostics
  Feature fixed;     // already in the fixed object's frame
  Feature mobile;    // in the mobile object's frame
  std::string fixed_name, mobile_name;
  bool has_value = false;
  double value = 0.0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  Orientation orientation = Orientation::kAligned;
  bool parallel = true;  // distance line-line: false = skew distance
  bool isRange() const { return !has_value; }
};

// One constraint for Problem::addConstraint, as a spec's constraint object says it (docs/spec.md
// §1.8), built by chaining:
//   problem.addConstraint(ConstraintSpec("distance", "table_top", "tcp").range(0.03, 0.09)
//                             .id("height"));
//   problem.addConstraint(ConstraintSpec("angle", "floor", "torch").atMost(0.6)
//                             .orientation(Orientation::kEither));
// Angles in radians. Without value(), range(), atLeast() or atMost() the value is 0, as the
// other addConstraint's default (the types that take none, coincident, parallel, …, ignore it).
class ConstraintSpec {
 public:
  ConstraintSpec(std::string type, std::string fixed_feature, std::string mobile_feature);
  ConstraintSpec& value(double v);               // exact
  ConstraintSpec& range(double min, double max);  // min <= max; min == max is value(min)
  ConstraintSpec& atLeast(double min);  // alone: open above; with atMost: both bounds
  ConstraintSpec& atMost(double max);   // alone: open below
  ConstraintSpec& orientation(Orientation o);
  // false: a line-line distance measured between skew lines (docs/spec.md §1.9).
  ConstraintSpec& parallel(bool p);
  ConstraintSpec& id(std::string id);

 private:
  friend struct Problem;
  std::string type_, fixed_, mobile_, id_;
  bool has_value_ = false, has_range_ = false;
  double value_ = 0.0;
  double min_ = -std::numeric_limits<double>::infinity();
  double max_ = std::numeric_limits<double>::infinity();
  Orientation orientation_ = Orientation::kAligned;
  bool parallel_ = true;
};

struct Problem {
  std::string name;
  // The spec gave its angles in degrees (`"units": {"angle": "deg"}`): values are stored in
  // radians, and messages that quote them convert back (added for issue 16).
  bool angles_in_degrees = false;
  ObjectSpec fixed;
  ObjectSpec mobile;
  std::vector<ObjectSpec> obstacles;
  std::vector<InputConstraint> constraints;
  // Objects (the fixed one or obstacles, by name) the mobile object may touch or pass into:
  // left out of collision filtering, as MoveIt's allowed collision matrix leaves a pair out.
  std::vector<std::string> allowed_contacts;

  // Convenience builders for the C++ API (no JSON).
  Problem& addFixedFeature(const std::string& name, const Feature& f);
  Problem& addMobileFeature(const std::string& name, const Feature& f);
  // Adds a constraint between named features; throws std::invalid_argument on unknown names.
  Problem& addConstraint(const std::string& type, const std::string& fixed_feature,
                         const std::string& mobile_feature, double value = 0.0,
                         Orientation orientation = Orientation::kAligned);
  // The same with everything a spec's constraint may say: an exact value, a range, a one-sided
  // range, orientation, parallel and id. std::invalid_argument on unknown feature names, a value
  // or bound that is NaN (or an infinite exact value), a min above its max, and a value given
  // both as exact and as a range.
  Problem& addConstraint(const ConstraintSpec& spec);
  // Largest coordinate magnitude (the solver measures its tolerance on the centred constraint
  // geometry instead: core/src/centring.hpp).
  double lengthScale() const;
};

}  // namespace relpos
