// solveComplete (stage.hpp): encode, solve the fiber, turn the proven-real roots into branches,
// check each against every input constraint, and say whether the list is proven complete.
#include "relpos/complete/stage.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>

#include "pose_conditions.hpp"
#include "real_root_proof.hpp"
#include "relpos/complete/fiber.hpp"
#include "relpos/complete/problem_encoding.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/manifolds/rotation/fixed.hpp"
#include "relpos/manifolds/separable.hpp"
#include "relpos/manifolds/translation/point.hpp"
#include "start_system.hpp"

namespace relpos::complete {
namespace {

// The last check's bound (docs/spec.md §6.5): a branch breaking a constraint by more is ours to
// drop, never to return.
constexpr double kCheckTolerances = 10.0;

struct Answer {
  std::vector<Branch> branches;
  std::vector<StageReport::Certificate> certificates;
  bool proven = true;  // no isolated root lost, none undecided (isolated_complete)
  std::string doubt;   // why not, when not
  // Every real solution is a branch (complete): the interval proof of each subproblem, and no
  // root of the answer in doubt.
  bool real_proven = true;
  std::string real_doubt;
  int proof_boxes = 0;
};

SourceMask allSources(const Problem& p) {
  const std::size_t n = p.constraints.size();
  return n >= 64 ? ~SourceMask{0} : (SourceMask{1} << n) - 1;
}

// Doubts about the count of isolated roots (the interval proof may still show every real one).
void doubt(Answer& a, std::string why) {
  if (a.proven) a.doubt = std::move(why);
  a.proven = false;
}

// Doubts about the real solutions (and so the isolated ones too).
void realDoubt(Answer& a, const std::string& why) {
  if (a.real_proven) a.real_doubt = why;
  a.real_proven = false;
}
void doubtBoth(Answer& a, const std::string& why) {
  doubt(a, why);
  realDoubt(a, why);
}

// The interval proof that every real root of the subproblem's encoding is a root found, within
// `boxes` (0: not tried).
template <typename Encoding>
void proveRealRoots(const Encoding& enc, const FiberResult& fiber, int boxes, Answer& a) {
  if (!a.real_proven) return;  // already in doubt: the proof could not change that
  if (boxes <= 0) return realDoubt(a, "the interval proof was not tried");
  detail::ExclusionOptions options;
  options.max_boxes = boxes;
  const detail::ExclusionResult proof = detail::proveRootsKnown(enc, fiber.roots, options);
  a.proof_boxes += proof.boxes;
  if (!proof.proven) realDoubt(a, proof.why);
}

// Whether a root's box reaches the real space (|Im x_i| ≤ radius everywhere): its root might be
// real even though the real test failed.
bool mayBeReal(const CertifiedRoot& r) {
  for (int i = 0; i < r.x.size(); ++i)
    if (std::abs(r.x[i].imag()) > r.radius) return false;
  return true;
}

// Whether the family's root count N rests on a trace test (a stored start system,
// docs/spec.md §8.5), not only on monodromy and numerical cross-checks: measured, a start system
// computed in the process can undercount (a random problem whose known pose was missed while its
// N roots were all found), so only a trace-tested N proves that every isolated root was found.
bool traceTestedCount(const Family& family) {
  const StartSystem* start = findStartSystem(family, false);  // solveFiber's, when it had one
  return start && start->check.find("+trace") != std::string::npos;
}

// The fiber's options for a family of `roots` roots: threads only where there are paths enough
// to share (starting a thread costs tens of microseconds).
FiberOptions fiberOptions(const StageOptions& options, const Family& family) {
  FiberOptions o;
  o.compute_start_system = options.compute_start_systems;
  const StartSystem* start = findStartSystem(family, false);
  const int threads = options.threads > 0
                          ? options.threads
                          : std::min(2, static_cast<int>(std::thread::hardware_concurrency()));
  if (start && start->roots.size() >= 16) o.threads = std::max(1, threads);
  return o;
}

std::string noStoredStartSystem(const Family& family) {
  return "no stored start system for the constraint signature '" + family.signature() +
         "' (computing one while solving is off, or would take more than " +
         std::to_string(detail::kSolvingStepBudget) + " tracking steps)";
}

// Every root the fiber certified: the non-real ones must be proven non-real for the list to be
// complete; the real ones go to `accept` (which says whether each is a solution).
template <typename Accept>
void collect(const FiberResult& fiber, bool trace_tested, Answer& a, Accept accept) {
  // A family without isolated roots: the encoding's roots are not isolated (a set of poses),
  // and an empty list proves nothing.
  if (fiber.root_count <= 0) return doubt(a, "the family has no isolated roots");
  if (!trace_tested)
    doubt(a,
          "the family's root count was not confirmed by a trace test (its start system was "
          "computed in this process)");
  if (!fiber.complete)
    doubt(a, std::to_string(fiber.roots.size()) + " of the family's " +
                 std::to_string(fiber.root_count) + " roots certified");
  for (const CertifiedRoot& r : fiber.roots) {
    if (!r.real) {
      if (mayBeReal(r)) doubt(a, "a root neither proven real nor proven complex");
      continue;
    }
    accept(r);
  }
}

// One subproblem (an orientation for each "either" that changes the equations).
bool solvePoseAlternative(const Problem& problem, const Registry& registry, const Tolerance& tol,
                          unsigned alternative, const StageOptions& options, Answer& a,
                          StageReport& report, std::string* why) {
  PoseEncoding enc;
  FiberResult fiber;
  bool trace_tested = false;
  // A second chart when the first loses roots (a pose with c·e = 0 is at infinity in it).
  for (int chart = 0; chart < 2; ++chart) {
    PoseEncoding e;
    if (!encodePose(problem, chart, &e, why, alternative)) return false;
    const PoseFamily family(e.equations, static_cast<int>(e.target.size()));
    FiberResult r = solveFiber(family, e.target, fiberOptions(options, family));
    if (r.start_system_missing) {
      *why = noStoredStartSystem(family);
      return false;
    }
    if (chart == 0)
      report.signature += (report.signature.empty() ? "" : " | ") + family.signature();
    if (chart == 0 || r.roots.size() > fiber.roots.size()) {
      fiber = std::move(r), enc = e;
      trace_tested = traceTestedCount(family);
    }
    if (fiber.complete) break;
  }
  report.root_count += fiber.root_count;
  report.roots_found += static_cast<int>(fiber.roots.size());
  const SourceMask sources = allSources(problem);
  collect(fiber, trace_tested, a, [&](const CertifiedRoot& r) {
    ++report.real_roots;
    Vector8d x;
    for (int i = 0; i < 8; ++i) x[i] = r.x[i].real();
    PoseEnclosure pe;
    if (!enclosePose(x, r.radius, enc.frames, &pe))
      return doubtBoth(a, "a real root's box holds no pose (e = 0)");
    for (const SignCheck& s : enc.signs) {
      const double along = s.fixed.dot(pe.pose.linear() * s.mobile);
      if (std::abs(along) < 0.5) return doubtBoth(a, "a parallelism's orientation undecided");
      if (s.sign * along < 0.0) return;  // a root of the equations, the other orientation
    }
    const double v = detail::worstViolation(problem, registry, tol, pe.pose);
    if (!(v <= kCheckTolerances))
      return doubtBoth(
          a, "a certified real root breaks a constraint by " + std::to_string(v) + " tolerances");
    Branch b;
    b.manifold.emplace<manifolds::SeparableManifold>(
        manifolds::rotation::Fixed(pe.pose.linear()),
        manifolds::translation::Point(
            Fundamental::pointPoint(Vector3d::Zero(), pe.pose.translation(), 0.0, sources)));
    b.sources = sources;
    a.branches.push_back(std::move(b));
    a.certificates.push_back({pe.radius, pe.angle});
  });
  // A pose's proof only where it can pay: no real pose found (docs/spec.md §8.4).
  const bool none = a.branches.empty() && report.real_roots == 0;
  proveRealRoots(enc, fiber, none ? options.pose_proof_boxes : 0, a);
  return true;
}

// Every subproblem; the list is complete only if each is.
bool solvePose(const Problem& problem, const Registry& registry, const Tolerance& tol,
               const StageOptions& options, Answer& a, StageReport& report, std::string* why) {
  PoseEncoding first;
  if (!encodePose(problem, 0, &first, why)) return false;
  if (first.alternatives > 3) {
    *why = std::to_string(first.alternatives) +
           " constraints with orientation 'either' that change the equations (at most 3)";
    return false;
  }
  for (unsigned alternative = 0; alternative < (1u << first.alternatives); ++alternative)
    if (!solvePoseAlternative(problem, registry, tol, alternative, options, a, report, why))
      return false;
  return true;
}

// The branch of every pose that puts the mobile line on the world line (point, direction): the
// rules' own coincident line-line (a spin about it and a slide along it), run on its constraint
// set (solveConstraintSet never calls the numeric stage again, as solve() would).
bool lineBranch(const Registry& registry, const Tolerance& tol, const LineEncoding& enc,
                const LineEnclosure& line, Branch* out) {
  const ConstraintType* type = registry.constraintType("coincident");
  if (!type || !type->decompose) return false;
  InputConstraint c;
  c.type = "coincident";
  c.fixed = Feature::makeLine(line.point, line.direction);
  c.mobile = Feature::makeLine(enc.mobile_point, enc.mobile_direction);
  c.has_value = true;
  Decomposition d;
  type->decompose(c, c.fixed, 1, d, type->context);
  if (d.unhandled || d.alternatives.size() != 1) return false;
  ConstraintSet set;
  for (const Fundamental& f : d.alternatives[0]) set.add(f);
  Workspace ws;
  Solution s;
  solveConstraintSet(set, tol, registry, SolverOptions(), ws, s);
  if (s.status != Status::kSolved || s.branches.size() != 1) return false;
  *out = s.branches[0];
  return true;
}

bool solveLine(const Problem& problem, const Registry& registry, const Tolerance& tol,
               const StageOptions& options, Answer& a, StageReport& report, std::string* why) {
  LineEncoding enc;
  if (!encodeLine(problem, tol, &enc, why)) return false;
  const LineFamily family(enc.equations, static_cast<int>(enc.target.size()));
  report.signature = family.signature();
  const FiberResult fiber = solveFiber(family, enc.target, fiberOptions(options, family));
  if (fiber.start_system_missing) {
    *why = noStoredStartSystem(family);
    return false;
  }
  report.root_count = fiber.root_count;
  report.roots_found = static_cast<int>(fiber.roots.size());
  const SourceMask sources = allSources(problem);
  collect(fiber, traceTestedCount(family), a, [&](const CertifiedRoot& r) {
    ++report.real_roots;
    Eigen::Matrix<double, 6, 1> x;
    for (int i = 0; i < 6; ++i) x[i] = r.x[i].real();
    LineEnclosure le;
    if (!encloseLine(x, r.radius, enc.frames, &le))
      return doubtBoth(a, "a real root's box holds no direction");
    for (const SignCheck& s : enc.signs) {
      const double along = s.fixed.dot(s.mobile.dot(enc.mobile_direction) * le.direction);
      if (std::abs(along) < 0.5) return doubtBoth(a, "a parallelism's orientation undecided");
      if (s.sign * along < 0.0) return;
    }
    Branch b;
    if (!lineBranch(registry, tol, enc, le, &b))
      return doubtBoth(a, "the rules did not solve the line's coincidence");
    const Manifold& m = *b.manifold;
    const double v = detail::worstViolation(problem, registry, tol, m.pose(referenceParams(m)));
    if (!(v <= kCheckTolerances))
      return doubtBoth(
          a, "a certified real line breaks a constraint by " + std::to_string(v) + " tolerances");
    b.sources = sources;
    a.branches.push_back(std::move(b));
    a.certificates.push_back({le.radius, le.angle});
  });
  proveRealRoots(enc, fiber, options.line_proof_boxes, a);
  return true;
}

bool decline(Solution& solution, const std::string& why) {
  solution.message = why;
  return false;
}

}  // namespace

bool solveComplete(const Problem& problem, const Registry& registry, const Tolerance& tol,
                   Solution& solution, StageReport* report, const StageOptions& options) {
  StageReport local;
  StageReport& rep = report ? *report : local;
  rep = StageReport{};
  if (problem.constraints.empty()) return decline(solution, "no constraints");
  if (!(detail::largestMagnitude(problem) <= 1e100))
    return decline(solution,
                   "coordinates or values beyond 1e100 (or not numbers): scale the problem");
  for (const InputConstraint& c : problem.constraints) {
    const ConstraintType* t = registry.constraintType(c.type);
    if (!t || t->origin != "built-in")
      return decline(solution, "constraint type '" + c.type + "' is not a built-in one");
  }
  Answer a;
  std::string why;
  const bool line = mobileFeaturesOnOneLine(problem, tol);
  const bool encoded = line ? solveLine(problem, registry, tol, options, a, rep, &why)
                            : solvePose(problem, registry, tol, options, a, rep, &why);
  if (!encoded) return decline(solution, why);
  rep.complete = a.proven;
  rep.real_complete = a.real_proven;
  rep.real_doubt = a.real_doubt;
  rep.proof_boxes = a.proof_boxes;
  // Every isolated root found proves no isolated pose missing, not that there is no
  // positive-dimensional set of poses besides, which no path reaches (a special member: features
  // on common axes, integer geometry; measured: random triples on grid geometry, a 1-DOF set next
  // to 12 complex roots). The interval proof over the bounded domain excludes those: with it,
  // the list is complete, and an empty list is a proof of inconsistency.
  if (a.branches.empty()) {
    if (a.real_proven) {
      solution.branches.clear();
      solution.status = Status::kInconsistent;
      solution.complete = solution.isolated_complete = true;
      solution.conflicts.clear();  // the solver names every constraint
      solution.message = "no pose satisfies the constraints: none of the " +
                         std::to_string(rep.roots_found) +
                         " certified solutions of their polynomial encoding is a real pose, and "
                         "an interval search of every pose in reach (" +
                         std::to_string(a.proof_boxes) + " boxes) finds no other";
      return true;
    }
    return decline(solution,
                   a.proven ? "no isolated real pose among all " + std::to_string(rep.root_count) +
                                  " certified solutions of the polynomial encoding, "
                                  "and no proof that no other pose exists: " +
                                  a.real_doubt
                            : "no solution among the roots found, and not proven: " + a.doubt);
  }
  solution.branches = std::move(a.branches);
  for (std::size_t i = 0; i < solution.branches.size(); ++i) {
    solution.branches[i].exact = false;
    solution.branches[i].certified = {a.certificates[i].radius, a.certificates[i].angle};
    solution.branches[i].origin = nullptr;
  }
  solution.complete = a.real_proven;
  // Every isolated root certified (and every "either"), or every real one listed.
  solution.isolated_complete = a.proven || a.real_proven;
  rep.certificates = std::move(a.certificates);
  solution.status = Status::kSolved;
  solution.conflicts.clear();
  solution.message.clear();
  return true;
}

}  // namespace relpos::complete
