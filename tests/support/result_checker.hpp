#pragma once
// Checks a solved problem the way a user relies on it, with every tolerance relative to the
// problem's own size (so the same check applies to a problem scaled ×1e-6, ×1e6 or moved 1e6
// away): no NaN or infinity in any pose nor in the result line, every sampled pose of every
// branch (and every nearest pose) satisfying every input constraint (the SPEC-only evaluator),
// and, when a solution is known, that pose on some branch.
#include <cstdint>
#include <limits>
#include <string>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"

namespace relpos::test {

// The problem's own length: the radius, about their centroid, of all its feature points where
// the spec places them (the mobile ones at the initial pose), or the largest radius or distance
// value if that is larger (1 when all are 0). Unchanged by rigid moves of the world or of either
// object's frame (the initial pose moving with it), and ×s when every length is ×s.
double problemSize(const Problem& p);
// The same measure without the floor: 0 for a problem whose features all lie at one point and
// whose constraints give no length (angles only), which has no size to scale.
double problemExtent(const Problem& p);

// The largest violation of any input constraint at X_WM, lengths divided by `size` (angles in
// radians): the evaluator run on the problem centred on its fixed features and scaled to size 1.
class RelativeEvaluator {
 public:
  RelativeEvaluator(const Problem& p, double size);
  double worst(const Isometry3d& X_WM, int* which = nullptr) const;
  // Translation error at the mobile features' centroid over the size, plus the rotation angle:
  // the distance between two placements of the mobile object as its features see it (unlike
  // poseDistance, unchanged when the mobile frame's origin is far from its features).
  double poseGap(const Isometry3d& A, const Isometry3d& B) const;

 private:
  Problem normalised_;
  Isometry3d to_normalised_;  // T(−centre)
  double size_;
  Vector3d mobile_centroid_;
};

struct CheckOptions {
  double size = 0.0;            // the problem's size; 0: problemSize(p)
  int samples_per_branch = 16;  // poses drawn per branch (fixed seed)
  std::uint64_t seed = 1;
  double violation_tolerance = 1e-7;  // relative to size (lengths) and in radians (angles)
  const Isometry3d* known = nullptr;  // a pose known to satisfy every constraint
  double known_tolerance = 1e-6;      // RelativeEvaluator::poseGap from it to the nearest branch
};

struct CheckReport {
  // What went wrong, by kind, each with a line saying where (empty: fine).
  std::string non_finite;  // a NaN/inf in a pose, a parameter or a bound
  std::string non_rigid;   // a finite pose whose rotation is not orthonormal (|RᵀR − I| > 1e-9)
  std::string violating;   // a branch pose violating an input constraint
  std::string known_lost;  // the known solution on no branch
  std::string bad_json;    // the result line holds a null SPEC does not allow, or does not parse
  std::string false_global;  // a pose of a branch nearer than its nearest said proven the nearest
  double worst_violation = 0.0;
  double known_gap = std::numeric_limits<double>::infinity();
  // The same gap through the branches' projections (Manifold::project, exact for a pose on the
  // manifold): when it is small but known_gap is not, the branch holds the known pose and the
  // nearest-pose search misses it.
  double known_projection_gap = std::numeric_limits<double>::infinity();
  bool knownFoundByProjection(double tolerance) const { return known_projection_gap <= tolerance; }
  bool ok() const {
    return non_finite.empty() && non_rigid.empty() && violating.empty() && known_lost.empty() &&
           bad_json.empty() && false_global.empty();
  }
  std::string summary() const;
};

CheckReport checkSolution(const Problem& p, const Solution& s, const CheckOptions& options);

// "rules: a, b, c" of the solution, for classifying failures by the rule that produced them.
std::string firedRules(const Solution& s);

}  // namespace relpos::test
