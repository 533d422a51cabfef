#pragma once
// Random problems built around a known solution: pick the mobile pose X_WM*, pick mobile features,
// then place fixed features so that every constraint holds at X_WM* (AGENTS: "pick a pose, place
// fixed features to fit"). Deterministic for a seed.
#include <random>
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"

namespace relpos::test {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(g_);
  }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(g_); }
  Vector3d unit();
  Vector3d point(double half = 2.0);
  // With `integer_geometry`, axis-aligned unit directions and integer points (special cases).
  Vector3d unitOrAxis(bool axis);
  Vector3d pointOrGrid(bool grid, double half = 2.0);
  Isometry3d pose(bool axis_aligned = false);
  Vector3d perpendicular(const Vector3d& u);  // random unit ⊥ u
  std::mt19937_64& engine() { return g_; }

 private:
  std::mt19937_64 g_;
};

// One kind of single constraint: type and feature kinds (fixed, mobile), with the DOF and number
// of branches a correct solver must report for generic geometry (derived by hand from the
// geometry, PMF Tables III/IV).
struct SingleKind {
  const char* type;
  FeatureKind fixed, mobile;
  Orientation orientation;
  int dof;
  int branches;
  const char* label;
};
const std::vector<SingleKind>& singleKinds();

struct KnownProblem {
  Problem problem;
  Isometry3d X_WM_star;  // a pose known to satisfy every constraint (up to `noise`)
  double noise = 0.0;    // perturbation of fixed features added by addConstraint
  bool special = false;  // integer geometry: the known pose may sit on a singular point
};

// Adds one constraint of `kind` (with a random value where it takes one) between a mobile feature
// and a fixed feature placed to fit X_WM_star. The mobile feature is new, or `reuse` when it is of
// the kind needed (so two constraints share a mobile point, line or plane).
void addConstraint(KnownProblem& kp, const SingleKind& kind, Rng& rng, bool grid = false,
                   const NamedFeature* reuse = nullptr);

KnownProblem emptyKnownProblem(Rng& rng, bool axis_aligned = false);

}  // namespace relpos::test
