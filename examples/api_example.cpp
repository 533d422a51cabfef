// The C++ API without JSON, as a robot controller calls it: build the PMF worked example
// (paper 003 §VI-A) in code, solve it, read its branches and evaluate poses.
#include <cstdio>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"

int main() {
  using Eigen::Vector3d;
  using relpos::Feature;

  // Once, at start-up: the registry of constraint types, rules and manifolds.
  relpos::Registry registry;
  relpos::registerBuiltins(registry);
  registry.freeze();

  // The problem: point P of the part on lines K and L of the base, and Q on Q.
  relpos::Problem problem;
  problem.addFixedFeature("K", Feature::makeLine({0, 0, 3}, {0, 1, 0}))
      .addFixedFeature("L", Feature::makeLine({0, 0, 3}, {0, 0, 1}))
      .addFixedFeature("Q", Feature::makePoint({-2, 0, 3}))
      .addMobileFeature("P", Feature::makePoint({0, 5, 3}))
      .addMobileFeature("Q", Feature::makePoint({0, 7, 3}));
  problem.addConstraint("coincident", "K", "P")
      .addConstraint("coincident", "L", "P")
      .addConstraint("coincident", "Q", "Q");

  // In the control loop: reuse the workspace and the solution, so solving allocates nothing.
  relpos::Workspace workspace;
  relpos::Solution solution;
  relpos::solve(problem, registry, relpos::SolverOptions(), workspace, solution);
  std::printf("%s\n", solution.briefReport().c_str());
  if (solution.status != relpos::Status::kSolved) return 1;

  for (const relpos::Branch& branch : solution.branches) {
    const relpos::Manifold& m = *branch.manifold;
    std::printf("branch: %s, %d DOF\n", m.describe().c_str(), m.dof());
    relpos::Params theta{};  // phi = 0: the pose of PMF eq. (17)
    Eigen::Isometry3d X_WM = m.pose(theta);
    Vector3d t = X_WM.translation();
    std::printf("pose(phi=0): translation [%g, %g, %g]\n", t.x(), t.y(), t.z());
    // The pose of this branch nearest to where the part is now.
    relpos::NearestPose n = relpos::nearestOnBranch(branch, problem.mobile.pose);
    std::printf("nearest: phi = %g, distance %g\n", n.parameters[0], n.distance);
  }
  return 0;
}
