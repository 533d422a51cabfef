#include "ranged_problems.hpp"

#include <algorithm>
#include <limits>

namespace relpos::test {

void widenToRange(InputConstraint& c, const SingleKind& kind, Rng& rng, int sides) {
  const std::string type = kind.type;
  if (!c.has_value || (type != "distance" && type != "angle" && type != "skew-distance")) return;
  const bool plane = kind.fixed == FeatureKind::kPlane || kind.mobile == FeatureKind::kPlane;
  const bool line_plane = kind.fixed != kind.mobile;
  double lo = -std::numeric_limits<double>::infinity(), hi = -lo;
  if ((type == "distance" || type == "skew-distance") && !plane) lo = 0.0;
  if (type == "angle") lo = line_plane ? -kPi / 2 : 0.0, hi = line_plane ? kPi / 2 : kPi;
  const double v = c.value;
  c.has_value = false;
  c.min = -std::numeric_limits<double>::infinity();
  c.max = std::numeric_limits<double>::infinity();
  if (sides != 2) c.min = std::max(lo, v - rng.uniform(0.05, 0.4));
  if (sides != 1) c.max = std::min(hi, v + rng.uniform(0.05, 0.4));
}

KnownProblem rangedProblem(Rng& rng, int index) {
  const auto& kinds = singleKinds();
  KnownProblem kp = emptyKnownProblem(rng, false);
  const int n = 2 + index % 2;
  NamedFeature shared;
  for (int k = 0; k < n; ++k) {
    const SingleKind& kind = kinds[rng.integer(0, static_cast<int>(kinds.size()) - 1)];
    addConstraint(kp, kind, rng, false, k > 0 && index % 3 == 0 ? &shared : nullptr);
    if (k == 0) shared = kp.problem.mobile.features.back();
    if ((index + k) % 2 == 0)
      widenToRange(kp.problem.constraints.back(), kind, rng, (index + k) % 3);
  }
  kp.problem.mobile.pose = kp.X_WM_star;
  return kp;
}

KnownProblem randomRangedProblem(Rng& rng, bool grid) {
  const auto& kinds = singleKinds();
  KnownProblem kp = emptyKnownProblem(rng, grid);
  const int n = rng.integer(2, 4);
  NamedFeature previous;
  for (int k = 0; k < n; ++k) {
    const SingleKind& kind =
        kinds[static_cast<std::size_t>(rng.integer(0, static_cast<int>(kinds.size()) - 1))];
    const bool share = k > 0 && rng.integer(0, 2) == 0;
    addConstraint(kp, kind, rng, grid, share ? &previous : nullptr);
    previous = kp.problem.mobile.features.back();
    if (rng.integer(0, 1) == 1)
      widenToRange(kp.problem.constraints.back(), kind, rng, rng.integer(0, 2));
  }
  kp.problem.mobile.pose = rng.pose();
  return kp;
}

}  // namespace relpos::test
