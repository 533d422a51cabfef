#include "solve_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/plugins/conformance.hpp"

namespace relpos::test {

const Registry& builtinRegistry() { return relpos::builtinRegistry(); }

Params sampleParams(const Manifold& m, std::mt19937_64& rng, double window) {
  return plugins::sampleParams(m, rng, window);
}

std::string poseText(const Isometry3d& X) { return plugins::poseText(X); }

double worstSampledViolation(const Problem& p, const Solution& s, int n, std::uint64_t seed,
                             std::string* where) {
  std::mt19937_64 rng(seed);
  double worst = 0.0;
  for (std::size_t b = 0; b < s.branches.size(); ++b) {
    const Manifold& m = *s.branches[b].manifold;
    for (int k = 0; k < n; ++k) {
      Params t = sampleParams(m, rng);
      Isometry3d X = m.pose(t);
      int which = -1;
      double v = worstViolation(p, X, &which);
      if (v > worst) {
        worst = v;
        if (where) {
          std::ostringstream os;
          os << "branch " << b << " (" << m.describe() << ") constraint " << which << " at "
             << poseText(X);
          *where = os.str();
        }
      }
    }
  }
  return worst;
}

bool someBranchContains(const Solution& s, const Isometry3d& X, double tol) {
  for (const Branch& b : s.branches) {
    Isometry3d Y = b.manifold->pose(nearestParams(*b.manifold, X));
    if (poseDistance(X, Y) <= tol) return true;
  }
  return false;
}

int dofOfBranchesContaining(const Solution& s, const Isometry3d& X, double tol) {
  int dof = -1;
  for (const Branch& b : s.branches) {
    Isometry3d Y = b.manifold->pose(nearestParams(*b.manifold, X));
    if (poseDistance(X, Y) <= tol) dof = std::max(dof, b.manifold->dof());
  }
  return dof;
}

std::string describeBranches(const Solution& s) {
  std::string out = std::string(toString(s.status)) + " " + s.message;
  for (const Branch& b : s.branches)
    out += "\n  " + b.manifold->describe() + ", " + std::to_string(b.manifold->dof()) + " DOF";
  return out;
}

}  // namespace relpos::test
