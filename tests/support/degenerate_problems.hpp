#pragma once
// Near-degenerate problems built around a known pose (issue 13, deliverable 6): lines and planes
// 1e-7 … 1e-12 rad from parallel, points 1e-8 apart, nearly concentric spheres, spheres that just
// touch a plane, a line, a sphere or a cylinder, cones 1e-8 apart, angles within 1e-9 of 0, π and
// ±π/2, nearly parallel cylinders. The geometry is placed in the world around the known mobile
// pose, so that pose satisfies every constraint to rounding (~1e-15 of the problem's size).
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "random_problems.hpp"

namespace relpos::test {

// An exact value, or a range (an infinite bound: open on that side).
struct ConstraintValue {
  bool exact = true;
  double value = 0.0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// Builds a problem in world coordinates: features are given where they are in the world (mobile
// ones at the known pose) and stored in their object's frame.
class WorldBuilder {
 public:
  explicit WorldBuilder(Rng& rng);
  Rng& rng() { return rng_; }
  KnownProblem& known() { return kp_; }
  // Adds a feature (its world placement) and returns its name.
  std::string fixed(const Feature& world);
  std::string mobile(const Feature& world);  // world placement at the known pose
  using Value = ConstraintValue;
  static Value exactly(double v) { return {true, v}; }
  static Value between(double lo, double hi) { return {false, 0.0, lo, hi}; }
  void constrain(const std::string& type, const std::string& fixed_name,
                 const std::string& mobile_name, Value v = Value(),
                 Orientation o = Orientation::kAligned, bool parallel = true);
  // One more constraint of a random single kind around the same pose (random_problems.hpp).
  void addGeneric();

 private:
  Rng& rng_;
  KnownProblem kp_;
  int features_ = 0;
};

struct DegenerateFamily {
  std::string name;
  std::string level_name;      // what a level is: "angle", "gap", ...
  std::vector<double> levels;  // e.g. the angle between the two lines
  int per_level = 16;          // instances per level (fixed seed)
  // How far (RelativeEvaluator::poseGap) the nearest branch pose may be from the known pose. The
  // data's rounding (1e-16 of the size) moves the exact solution by conditioning × 1e-16: 1/θ
  // for lines θ apart, sqrt for a sphere just touching a plane (a circle of radius r·sqrt(2η)
  // when the plane cuts it by η). Never below 1e-6 (result_checker's default).
  std::function<double(double level)> known_tolerance;
  // The known pose's own largest relative violation (the generator's promise): rounding, or the
  // gap η itself where the family misses exact contact by η on purpose.
  std::function<double(double level)> known_slack;
  // Builds instance `k` of `level`.
  std::function<void(WorldBuilder&, double level, int k)> build;
};

const std::vector<DegenerateFamily>& degenerateFamilies();

}  // namespace relpos::test
