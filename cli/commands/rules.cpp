// relpos rules (docs/spec.md §3): what the registry holds, or how often each rule case fired.
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "cli.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::cli {

namespace {

// How often each rule case fired over a folder of specs, and which never fired.
int cmdRuleCoverage(const Args& a, const Registry& reg) {
  if (a.positional.empty()) throw UsageError("rules --coverage needs a folder or spec files");
  std::map<std::string, int> count;
  for (const auto& r : reg.rules()) {
    if (r.cases.empty()) count[r.name] = 0;
    for (const auto& c : r.cases) count[c.name] = 0;
  }
  relpos::Workspace ws;
  relpos::Solution sol;
  int invalid = 0, specs = 0;
  for (const auto& f : specFiles(a.positional)) {
    relpos::Problem pb;
    if (!loadProblem(f, reg, &pb)) {
      ++invalid;
      continue;
    }
    ++specs;
    relpos::solve(pb, reg, relpos::SolverOptions(), ws, sol);
    for (const char* name : sol.ruleNames()) ++count[name];
  }
  int never = 0;
  for (const auto& r : reg.rules()) {
    auto row = [&](const std::string& name, const std::string& citation) {
      std::printf("%6d  %-36s %s\n", count[name], name.c_str(), citation.c_str());
      never += count[name] == 0;
    };
    if (r.cases.empty()) row(r.name, r.citation);
    for (const auto& c : r.cases) row(c.name, c.citation);
  }
  std::printf("%d specs solved, %d invalid; %d rule cases never fired", specs, invalid, never);
  if (never) {
    std::printf(":");
    for (const auto& [name, n] : count)
      if (n == 0) std::printf(" %s", name.c_str());
  }
  std::printf("\n");
  return invalid ? kExitInvalid : kExitOk;
}

}  // namespace

int cmdRules(const Args& a, const Registry& reg) {
  if (a.coverage) return cmdRuleCoverage(a, reg);
  if (!a.positional.empty()) throw UsageError("rules takes no arguments (or --coverage DIR)");
  std::cout << "constraint types:\n";
  for (const auto& t : reg.constraintTypes()) {
    std::cout << "  " << t.name << "  [" << t.origin << "]  " << t.description << "\n    accepts:";
    for (const auto& p : t.accepts)
      std::cout << " " << relpos::toString(p.fixed) << "-" << relpos::toString(p.mobile);
    std::cout << "\n";
  }
  std::cout << "combination rules:\n";
  for (const auto& r : reg.rules()) {
    std::cout << "  " << r.name << "  (" << relpos::toString(r.first) << " + "
              << relpos::toString(r.second) << ")  [" << r.origin << "]  " << r.citation << "\n";
    for (const auto& c : r.cases) std::cout << "    " << c.name << "  " << c.citation << "\n";
  }
  std::cout << "manifolds:\n";
  for (const auto& m : reg.manifolds())
    std::cout << "  " << m.name << "  [" << m.origin << "]  " << m.description << "\n";
  std::cout << "matchers:\n";
  for (const auto& m : reg.matchers()) std::cout << "  " << m.name << "  [" << m.origin << "]\n";
  if (!reg.customKinds().empty()) {
    std::cout << "custom fundamental kinds:\n";
    for (const auto& k : reg.customKinds())
      std::cout << "  " << k.name << "  [" << k.origin << "]  " << k.description << "\n";
  }
  if (const relpos::FallbackInfo* stage = reg.fallback())  // docs/spec.md §8
    std::cout << "numeric stage:\n  " << stage->name << "  [" << stage->origin << "]\n";
  return kExitOk;
}

}  // namespace relpos::cli
