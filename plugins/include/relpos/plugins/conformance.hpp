#pragma once
// The conformance kits (STYLE.md §10), installed with the SDK so plugin authors run on their
// items exactly the checks the built-ins pass (as Ceres ships its manifold test utilities).
// Framework-free: each check appends readable failures to a Report, each named by the invariant
// that broke ("[params-round-trip] DESCRIBE: WHAT"); wrap it in any test framework
// (`EXPECT_TRUE(report.ok()) << report.text();`).
#include <random>
#include <string>
#include <vector>

#include "relpos/core/manifold.hpp"
#include "relpos/core/registry.hpp"

namespace relpos::plugins {

struct Report {
  std::vector<std::string> failures;
  int checked = 0;  // samples or rule outputs actually examined
  bool ok() const { return failures.empty(); }
  std::string text() const;
};

// How far X_WM is from satisfying f (0 inside its [lo, hi]), written from PMF §III; a custom
// kind is measured by the residual its plugin registered (so `registry` is needed for those).
double fundamentalResidual(const Fundamental& f, const Isometry3d& X_WM,
                           const Registry* registry = nullptr);

// A pose as text a failure message can show (and a test can paste back): position, quaternion.
std::string poseText(const Isometry3d& X);

// Parameters drawn uniformly within the manifold's bounds (unbounded lengths within ±window of
// 0): relpos::sampleParameters about parameters 0.
Params sampleParams(const Manifold& m, std::mt19937_64& rng, double window = 3.0);

// The manifold suite, by invariant: dof-in-range, dof-split (rotational + translational = dof),
// parameter-named, parameter-bounds (min <= max), periodic-is-angle, pose-rigid,
// project-in-bounds, params-round-trip (pose(project(X)) = X on the manifold),
// contains-on-manifold, nearest-not-farther (than the projection), search-distance
// (searchDistance weighs θ as poseWithTail's pose).
void checkManifold(const Manifold& m, std::uint64_t seed, Report& report, int samples = 40);

// Every pose sampled from the synthesised `output` set satisfies both inputs a and b. Returns false
// (checking nothing) when the registry cannot synthesise the output on its own.
bool outputImpliesInputs(const Registry& registry, const std::vector<Fundamental>& output,
                         const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                         std::mt19937_64& rng, std::string* bad);

// The rule suite for one pair: applies the rule to (a, b), then checks that what it answered is
// right, by invariant: case-named (a rule with cases names the one that fired),
// redundant-is-implied (a dropped constraint is implied by the kept one),
// replacement-implies-pair (every replacement set admits only poses satisfying both inputs),
// satisfiable-not-incompatible and known-pose-kept (`known`, a pose satisfying a and b when
// given, is never declared incompatible and satisfies some replacement set).
void checkRule(const Registry& registry, const RuleInfo& rule, const Fundamental& a,
               const Fundamental& b, const Tolerance& tol, std::mt19937_64& rng, Report& report,
               const Isometry3d* known = nullptr);

}  // namespace relpos::plugins
