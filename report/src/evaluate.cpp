#include "relpos/report/evaluate.hpp"

#include <exception>
#include <limits>
#include <optional>
#include <random>

#include "relpos/collision/branch_filter.hpp"
#include "relpos/core/solver.hpp"
#include "parameter_motion.hpp"
#include "relpos/io/result_writer.hpp"

namespace relpos {
namespace {

// The message, with the user's constraint ids next to the indices (SPEC: ids are echoed).
void resultMessage(const Problem& problem, const Solution& solution, std::string& message) {
  message = solution.message;
  std::string ids;
  for (int k : solution.conflicts) {
    const std::string& id = problem.constraints[static_cast<std::size_t>(k)].id;
    if (!id.empty()) ids += (ids.empty() ? "" : ", ") + std::to_string(k) + " = '" + id + "'";
  }
  if (!ids.empty()) message += " (constraints " + ids + ")";
}

// Everything but the collision fields: each branch's description, nearest pose and samples.
// Runs the branches' code, which may throw.
void evaluateBranches(const Problem& problem, const Solution& solution, const ReportOptions& opt,
                      Report& r) {
  r.name = problem.name;
  r.status = solution.status;
  r.complete = solution.complete;
  r.isolated_complete = solution.isolated_complete;
  resultMessage(problem, solution, r.message);
  r.conflicts.assign(solution.conflicts.begin(), solution.conflicts.end());
  r.redundant.assign(solution.redundant.begin(), solution.redundant.end());
  r.rules.assign(solution.rules.begin(), solution.rules.end());
  r.rule_names = solution.rule_names;
  r.solve_us = solution.solve_us;
  r.collision_checked = false;
  r.collision.clear();
  r.checked_against.clear();
  r.collision_free_branches = 0;
  r.best = -1;
  r.samples.clear();
  r.branches.resize(solution.branches.size());
  double best_d = std::numeric_limits<double>::infinity();
  // Seeding the generator costs more than writing a branch: only when samples are asked for.
  std::optional<std::mt19937_64> rng;
  if (opt.samples > 0) rng.emplace(opt.seed);
  for (std::size_t b = 0; b < solution.branches.size(); ++b) {
    const Branch& branch = solution.branches[b];
    const Manifold& m = *branch.manifold;
    BranchReport& br = r.branches[b];
    br.dof = m.dof();
    br.rotational_dof = m.rotationalDof();
    br.translational_dof = br.rotational_dof >= 0 ? m.translationalDof() : -1;
    br.manifold = m.describe();
    br.exact = branch.exact;
    br.certified = branch.certified;
    for (int i = 0; i < br.dof; ++i) br.parameters[static_cast<std::size_t>(i)] = m.parameter(i);
    br.nearest = nearestOnBranch(branch, problem.mobile.pose);
    detail::parameterMotions(problem, branch, br.nearest.parameters, br.motions);
    if (br.nearest.distance < best_d) best_d = br.nearest.distance, r.best = static_cast<int>(b);
    br.first_sample = r.samples.size();
    br.sample_count = opt.samples > 0 ? static_cast<std::size_t>(opt.samples) : 0;
    for (std::size_t k = 0; k < br.sample_count; ++k) {
      const Params t = sampleParameters(m, br.nearest.parameters, opt.window, *rng);
      r.samples.push_back({t, m.pose(t)});
    }
  }
}

// The collision fields of docs/spec.md §2: each branch's verdict at its nearest pose, its nearest
// collision-free pose and free samples. Runs the branches' code, which may throw.
void evaluateCollisions(const Solution& solution, const ReportOptions& opt,
                        const collision::Scene& scene, const Isometry3d& initial, Report& r) {
  collision::FilterOptions filter;
  filter.clearance = opt.clearance;
  filter.samples = opt.collision_samples;
  filter.window = opt.window;
  filter.seed = opt.seed;
  r.collision_checked = true;
  r.checked_against = scene.checkedAgainst();
  r.clearance = opt.clearance;
  r.collision.resize(solution.branches.size());
  for (std::size_t b = 0; b < solution.branches.size(); ++b) {
    r.collision[b] = collision::filterBranch(scene, solution.branches[b], r.branches[b].nearest,
                                             initial, filter);
    r.collision_free_branches +=
        r.collision[b].has_nearest_free || !r.collision[b].free_samples.empty();
  }
}

// What a throw says, whatever was thrown.
std::string whatOf(std::exception_ptr e) {
  try {
    std::rethrow_exception(e);
  } catch (const std::exception& x) {
    return x.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}

}  // namespace

void evaluate(const Problem& problem, const Solution& solution, const ReportOptions& opt,
              Report& report, const collision::Scene* scene) {
  // A plugin's manifold that throws makes the answer an `unhandled` one naming the plugin, not a
  // lost result. (The message's "writing the result" dates from when the writer searched.)
  try {
    evaluateBranches(problem, solution, opt, report);
  } catch (...) {
    const Solution unhandled =
        unhandledAfterThrow(solution, "writing the result", whatOf(std::current_exception()));
    evaluateBranches(problem, unhandled, opt, report);  // no branches: nothing left to throw
    report.collision_checked = scene != nullptr;        // and none to filter
    return;
  }
  if (!scene) return;
  try {
    evaluateCollisions(solution, opt, *scene, problem.mobile.pose, report);
  } catch (...) {
    const Solution unhandled =
        unhandledAfterThrow(solution, "filtering collisions", whatOf(std::current_exception()));
    evaluateBranches(problem, unhandled, opt, report);
    report.collision_checked = true;  // collision_free_branches: 0
  }
}

Report evaluate(const Problem& problem, const Solution& solution, const ReportOptions& options,
                const collision::Scene* scene) {
  Report report;
  evaluate(problem, solution, options, report, scene);
  return report;
}

void writeResultLine(const Problem& problem, const Solution& solution, const ReportOptions& options,
                     std::string& out) {
  // One per thread: a batch worker's lines reuse its buffers.
  thread_local Report report;
  evaluate(problem, solution, options, report);
  writeReport(report, kResultLine, out);
}

}  // namespace relpos
