#include "fallback.hpp"

#include <cmath>
#include <exception>
#include <string>

#include "branch_check.hpp"

namespace relpos::detail {
namespace {

// The rules' answer again, with `message`: nothing of what the numeric stage left is kept (its
// branches' code does not run again), only the rules that fired.
void restoreUnhandled(Solution& solution, std::string message) {
  solution.status = Status::kUnhandled;
  solution.complete = false;
  solution.isolated_complete = false;
  solution.branches.clear();
  solution.conflicts.clear();
  solution.redundant.clear();
  solution.message = std::move(message);
}

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0.0; }

// Every index of `list` names an input constraint.
bool indicesInRange(const std::vector<int>& list, std::size_t n) {
  for (int i : list)
    if (i < 0 || static_cast<std::size_t>(i) >= n) return false;
  return true;
}

// What makes the numeric stage's answer unusable, in words ("" when nothing), after completing
// what it may leave out: a solved answer's message is "" (docs/spec.md §2.2), an inconsistent
// one is complete and names its conflicts (every constraint when it named none) and why. Each
// branch records the stage's plugin (Branch::origin), so that what its manifold throws later
// names it. Calls the branches' cheap methods, which may throw (the caller guards).
std::string checkAnswer(const Problem& problem, const SolverOptions& options,
                        const FallbackInfo& stage, Solution& s) {
  const std::size_t n = problem.constraints.size();
  if (!indicesInRange(s.conflicts, n) || !indicesInRange(s.redundant, n))
    return "answered with a constraint index out of range";
  if (s.complete) s.isolated_complete = true;  // every solution listed: every isolated one too
  if (s.status == Status::kInconsistent) {
    if (!s.branches.empty()) return "answered inconsistent with branches";
    s.complete = s.isolated_complete = true;  // proven: no pose, so none is missing
    if (s.conflicts.empty())
      for (std::size_t i = 0; i < n; ++i) s.conflicts.push_back(static_cast<int>(i));
    if (s.message.empty()) s.message = "no pose satisfies the constraints (" + stage.name + ")";
    return "";
  }
  if (s.status != Status::kSolved) return "answered without a solved or inconsistent status";
  if (s.branches.empty()) return "answered solved without branches";
  if (s.branches.size() > static_cast<std::size_t>(options.max_branches))
    return "answered with too many solution branches";
  s.message.clear();
  s.conflicts.clear();
  for (std::size_t b = 0; b < s.branches.size(); ++b) {
    Branch& branch = s.branches[b];
    if (!branch.origin) branch.origin = stage.library;
    const std::string which = "branch " + std::to_string(b);
    const char* type = "?";
    const char* call = "";
    const std::string problem_text = unusable(branch.manifold, type, call);
    if (!problem_text.empty()) return "made an unusable " + which + ": " + problem_text;
    const Certificate& c = branch.certified;
    if (!finiteNonNegative(c.radius) || !finiteNonNegative(c.angle))
      return "made " + which + " with a certificate that is not finite and non-negative";
    if (branch.exact && (c.radius != 0.0 || c.angle != 0.0))
      return "made " + which + " exact with a certificate";
  }
  return "";
}

}  // namespace

void answerByFallback(const Problem& problem, const Registry& registry,
                      const SolverOptions& options, const Tolerance& tol, Solution& solution) {
  const FallbackInfo& stage = *registry.fallback();
  // Options the solver refused are the caller's to fix, whoever would solve.
  if (!options.isValid(nullptr)) return;
  const std::string rules_reason = solution.message;
  auto who = [&] { return "the numeric stage '" + stage.name + "'" + originNote(stage.origin); };
  bool answered = false;
  std::string bad, what;
  bool threw = true;
  try {
    answered = stage.fn(problem, registry, tol, solution, stage.context);
    if (answered && solution.status != Status::kUnhandled)
      bad = checkAnswer(problem, options, stage, solution);
    threw = false;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "an exception that is not a std::exception";
  }
  if (threw) return restoreUnhandled(solution, rules_reason + "; " + who() + " threw: " + what);
  if (!answered || solution.status == Status::kUnhandled) {
    // Not answered: the rules' reason, and the stage's own when it gave one.
    const bool own = !solution.message.empty() && solution.message != rules_reason;
    return restoreUnhandled(
        solution, own ? rules_reason + "; " + who() + ": " + solution.message : rules_reason);
  }
  if (!bad.empty()) return restoreUnhandled(solution, rules_reason + "; " + who() + " " + bad);
  // The same last check as the rules' branches (§6.5): a certified pose must meet every input
  // constraint by the constraint type's own reading too.
  checkBranches(problem, registry, tol, solution);
  if (solution.status == Status::kUnhandled)
    restoreUnhandled(solution, rules_reason + "; " + who() + ": " + solution.message);
}

}  // namespace relpos::detail
