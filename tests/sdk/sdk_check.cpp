// Run by the out-of-tree SDK test: loads the plugins this project built against the installed
// relpos, solves the plugin specs, and runs the installed conformance kits on every branch and on
// the plugin's rule. Exit 0 when everything conforms; otherwise the failures on stderr.
#include <cmath>
#include <cstdio>
#include <random>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/conformance.hpp"
#include "relpos/plugins/loader.hpp"

int main() {
  relpos::Registry registry;
  relpos::registerBuiltins(registry);
  for (const char* path : {SYMMETRIC_PLUGIN, HELICAL_PLUGIN}) {
    std::string error;
    if (!relpos::plugins::loadPlugin(path, registry, &error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
  }
  registry.freeze();

  relpos::plugins::Report report;
  int branches = 0;
  for (const char* name : {"symmetric-centred-grasp", "helical-screw-insertion"}) {
    const std::string file = std::string(PLUGIN_SPECS) + "/" + name + ".json";
    relpos::ParseResult parsed = relpos::parseSpecFile(file, registry);
    if (!parsed.problem) {
      std::fprintf(stderr, "%s: cannot parse\n", file.c_str());
      return 1;
    }
    const relpos::Solution s = relpos::solve(*parsed.problem, registry);
    if (s.status != relpos::Status::kSolved) {
      std::fprintf(stderr, "%s: %s\n", name, s.message.c_str());
      return 1;
    }
    for (const auto& b : s.branches)
      relpos::plugins::checkManifold(*b.manifold, ++branches, report);
  }

  // Plugin state lives in the registry (callback contexts, ABI 6): in a second registry where
  // the helical kind has another index, the thread still solves.
  {
    relpos::Registry other;
    relpos::registerBuiltins(other);
    other.addCustomKind(
        {"taken-first", "moves helical to index 1",
         [](const relpos::Fundamental&, const relpos::Isometry3d&, const void*) { return 0.0; }});
    std::string error;
    if (!relpos::plugins::loadPlugin(HELICAL_PLUGIN, other, &error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    other.freeze();
    const std::string file = std::string(PLUGIN_SPECS) + "/helical-screw-insertion.json";
    relpos::ParseResult parsed = relpos::parseSpecFile(file, other);
    const relpos::Solution s =
        parsed.problem ? relpos::solve(*parsed.problem, other) : relpos::Solution();
    if (s.status != relpos::Status::kSolved) {
      std::fprintf(stderr, "helical in a second registry: %s\n", s.message.c_str());
      return 1;
    }
  }

  // The plugin's rule on shell/plane pairs around known poses.
  const relpos::RuleInfo* rule = nullptr;
  for (const auto& r : registry.rules())
    if (r.name == "shell-cut:pp+pplane") rule = &r;
  if (!rule) {
    std::fprintf(stderr, "the symmetric plugin's rule is missing\n");
    return 1;
  }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const relpos::Tolerance tol = relpos::Tolerance::forScale(3.0);
  for (int k = 0; k < 50; ++k) {
    relpos::Isometry3d X = relpos::Isometry3d::Identity();
    X.linear() = relpos::axisAngle(relpos::Vector3d(u(rng), u(rng), u(rng)).normalized(), u(rng));
    X.translation() = relpos::Vector3d(u(rng), u(rng), u(rng));
    const relpos::Vector3d p_m(u(rng), u(rng), u(rng)), centre(u(rng), u(rng), u(rng));
    const double d = (X * p_m - centre).norm();
    relpos::Fundamental shell = relpos::Fundamental::pointPoint(p_m, centre, 0.0, 1);
    shell.lo = std::max(0.0, d - 0.2);
    shell.hi = d + 0.1;
    const relpos::Fundamental plane = relpos::Fundamental::pointPlane(
        relpos::Side::kMobile, p_m, X * p_m, relpos::Vector3d(u(rng), u(rng), 1.0), 0.0, 2);
    relpos::plugins::checkRule(registry, *rule, shell, plane, tol, rng, report, &X);
  }
  if (!report.ok() || branches < 3 || report.checked < 100) {
    std::fprintf(stderr, "%s(branches %d, checked %d)\n", report.text().c_str(), branches,
                 report.checked);
    return 1;
  }
  std::printf("sdk check: %d branches and the plugin rule conform (%d checks)\n", branches,
              report.checked);
  return 0;
}
