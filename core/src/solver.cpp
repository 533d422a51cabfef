#include "relpos/core/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "branch_check.hpp"
#include "centring.hpp"
#include "fallback.hpp"
#include "relpos/core/branch_sink.hpp"
#include "unmatched_hint.hpp"

namespace relpos {

bool SolverOptions::isValid(std::string* why) const {
  if (max_branches < 1 || max_branches > 4096) {
    if (why) *why = "max_branches must be in [1, 4096]";
    return false;
  }
  if (max_rule_steps < 1) {
    if (why) *why = "max_rule_steps must be positive";
    return false;
  }
  if (!(length_tolerance > 0 && length_tolerance < 1e-2 && angle_tolerance > 0 &&
        angle_tolerance < 1e-2)) {
    if (why) *why = "tolerances must be in (0, 0.01)";
    return false;
  }
  return true;
}

Workspace::Workspace() {
  pending.reserve(64);
  problems.reserve(4);
}

namespace {

enum class SetOutcome { kCombined, kInconsistent, kUnhandled };

struct SolveState {
  const Registry& registry;
  const SolverOptions& options;
  Tolerance tol;  // decided once the decomposed geometry is measured
  Workspace& ws;
  Solution& solution;
  SourceMask conflicts = 0;
  const char* conflict_reason = "";
  std::string unhandled;  // first reason an alternative could not be decided
  bool any_unhandled = false;
  bool deferred = false;    // a rule waited for better-conditioned pairs (RuleOutput::defer)
  bool last_round = false;  // combining what waited (combineInRounds)
  const Problem* problem = nullptr;  // what the sets came from (null: solveConstraintSet)
};

void setUnhandled(SolveState& st, const std::string& why) {
  if (!st.any_unhandled) st.unhandled = why;
  st.any_unhandled = true;
}

// Every call into registered code (a plugin's, or a built-in registered the same way) goes
// through guarded(): an exception from it becomes the solve's `unhandled` reason, "ITEM (plugin
// PATH) threw: WHAT", instead of unwinding through a batch worker or out of main. The try costs
// nothing while nothing throws; `item` (which allocates) is only called when something did.
template <typename Call, typename Item>
bool guarded(SolveState& st, Call&& call, Item&& item) {
  std::string what;
  try {
    call();
    return true;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "an exception that is not a std::exception";
  }
  setUnhandled(st, item() + " threw: " + what);
  return false;
}

// Every input constraint a set's fundamentals came from.
SourceMask sourcesOf(const ConstraintSet& set) {
  SourceMask m = 0;
  for (const Fundamental& f : set.translational) m |= f.sources;
  for (const Fundamental& f : set.rotational) m |= f.sources;
  return m;
}

std::string describeSet(const ConstraintSet& set) {
  std::string s;
  auto list = [&s](const char* title, const auto& v) {
    if (v.empty()) return;
    s += title;
    for (std::size_t i = 0; i < v.size(); ++i) {
      s += i ? ", " : " ";
      s += toString(v[i].kind);
      char buf[64];
      if (v[i].exact())
        std::snprintf(buf, sizeof buf, " %.6g", v[i].value());
      else
        std::snprintf(buf, sizeof buf, " %.6g..%.6g", v[i].lo, v[i].hi);
      s += buf;
      s += " (from constraint";
      for (int k = 0; k < 64; ++k)
        if (v[i].sources >> k & 1) s += " " + std::to_string(k);
      s += ")";
    }
    s += ";";
  };
  list(" translational:", set.translational);
  list(" rotational:", set.rotational);
  return s;
}

// The largest uncertainty among the angle constraints a rule derived (radians; a translational
// one's is a length, which the final check bounds).
double derivedErr(const RuleOutput& out) {
  double e = 0.0;
  for (const auto& alt : out.alternatives)
    for (const Fundamental& f : alt) {
      if (f.translational()) continue;
      if (std::isnan(f.err)) return f.err;
      e = std::max(e, f.err);
    }
  return e;
}
bool tooUncertain(const RuleOutput& out) { return !(derivedErr(out) <= kMaxDerivedErr); }
std::string derivedErrText(const RuleOutput& out) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", derivedErr(out));
  return buf;
}

// The solution keeps the registry's plugin libraries and rule names alive. Assigned only when they
// differ: a solve into a reused Solution then costs no atomic reference counting.
void shareRegistryData(const Registry& registry, Solution& solution) {
  if (solution.libraries != registry.loadedLibraries())
    solution.libraries = registry.loadedLibraries();
  if (solution.rule_names != registry.ruleNames()) solution.rule_names = registry.ruleNames();
}

// Which case of rule `index` fired (-1, the rule itself, for a `fired` that names no case).
RuleCaseId caseId(int index, const RuleInfo& rule, int fired) {
  const bool is_case = fired >= 0 && fired < static_cast<int>(rule.cases.size());
  return {static_cast<std::uint16_t>(index), static_cast<std::int16_t>(is_case ? fired : -1)};
}

// Rewrites one list (C_T or C_R) of `set` pairwise until no rule applies. Alternatives other than
// the first are pushed onto the workspace's pending stack.
SetOutcome combineList(SolveState& st, std::size_t set_index, bool translational, int& steps) {
  RuleOutput& out = st.ws.rule_out;
restart:
  ConstraintSet& set = st.ws.pending[set_index];
  auto& list = translational ? set.translational : set.rotational;
  for (std::size_t i = 0; i < list.size(); ++i) {
    for (std::size_t j = i + 1; j < list.size(); ++j) {
      if (set.wasTested(list[i], list[j])) continue;
      // The PMF rules are for exact values; a pair with a range goes only to the rules that
      // declare they handle ranges (Somani's), the rest is left to the matchers.
      const bool ranged = !list[i].exact() || !list[j].exact();
      bool pair_deferred = false;
      for (const auto& entry : st.registry.rulesFor(list[i].kind, list[j].kind)) {
        const RuleInfo& rule = st.registry.rules()[entry.rule];
        if (ranged && !rule.handles_ranges) continue;
        const Fundamental& a = entry.swapped ? list[j] : list[i];
        const Fundamental& b = entry.swapped ? list[i] : list[j];
        out.reset();
        if (!guarded(
                st, [&] { rule.fn(a, b, st.tol, out, rule.context); },
                [&] { return "rule '" + rule.name + "'" + originNote(rule.origin); }))
          return SetOutcome::kUnhandled;
        if (out.verdict == RuleVerdict::kNoChange) {
          pair_deferred = pair_deferred || out.deferred;
          continue;
        }
        if (out.verdict == RuleVerdict::kReplace && tooUncertain(out)) {
          // First round: wait for a pair that derives the same better (a third point far from
          // two nearly coincident ones); in the last, nothing decides it within the tolerance.
          if (!st.last_round) {
            pair_deferred = true;
            continue;
          }
          setUnhandled(st, "rule '" + rule.firedName(out.fired) +
                               "' derives a direction known only to " + derivedErrText(out) +
                               " rad: the features it reads are too close together to decide "
                               "the problem within the tolerance");
          return SetOutcome::kUnhandled;
        }
        st.solution.noteRule(caseId(entry.rule, rule, out.fired));
        if (++steps > st.options.max_rule_steps) {
          setUnhandled(st, "the combination rules did not settle within " +
                               std::to_string(st.options.max_rule_steps) + " steps");
          return SetOutcome::kUnhandled;
        }
        const SourceMask both = a.sources | b.sources;
        switch (out.verdict) {
          case RuleVerdict::kIncompatible:
            st.conflicts |= both;
            st.conflict_reason = out.reason;
            return SetOutcome::kInconsistent;
          case RuleVerdict::kRedundantFirst:
          case RuleVerdict::kRedundantSecond: {
            bool drop_a = out.verdict == RuleVerdict::kRedundantFirst;
            std::size_t drop = (drop_a != entry.swapped) ? i : j;
            set.dropped_redundant |= list[drop].sources;
            list.erase(drop);
            goto restart;
          }
          case RuleVerdict::kReplace: {
            // Remove the pair, then add each alternative's constraints (sources: both inputs).
            list.erase(j);
            list.erase(i);
            for (std::size_t k = 1; k < out.alternatives.size(); ++k) {
              if (static_cast<int>(st.ws.pending.size()) >= st.options.max_branches) {
                setUnhandled(st, "more than " + std::to_string(st.options.max_branches) +
                                     " alternative constraint sets");
                return SetOutcome::kUnhandled;
              }
              st.ws.pending.push_back(st.ws.pending[set_index]);
              ConstraintSet& alt = st.ws.pending.back();
              for (Fundamental f : out.alternatives[k]) {
                f.sources |= both;
                alt.add(f);
              }
            }
            ConstraintSet& cur = st.ws.pending[set_index];
            for (Fundamental f : out.alternatives[0]) {
              f.sources |= both;
              cur.add(f);
            }
            if (cur.overflow) {
              setUnhandled(st, "too many fundamental constraints");
              return SetOutcome::kUnhandled;
            }
            goto restart;
          }
          case RuleVerdict::kNoChange:
            break;
        }
      }
      // A deferred pair is asked again in the round without the conditioning bound.
      if (pair_deferred)
        st.deferred = true;
      else
        set.markTested(list[i], list[j]);
    }
  }
  return SetOutcome::kCombined;
}

// Combines one list in two rounds: first with the conditioning bound, so that the pairs that
// decide well go first; then, if a pair waited (RuleOutput::defer) and is still there, to decide
// what only it can — as far as the input's rounding, so magnified, stays below the angle
// tolerance (a gain of ~3e5 at the default 1e-9). Beyond that the pair decides nothing within the
// tolerance (two lines crossing at 1e-9 rad meet anywhere along a stretch longer than the
// problem; cones about axes 1e-8 apart meet in directions 1e-5 off) and is left to the matchers,
// or the problem unhandled.
SetOutcome combineInRounds(SolveState& st, std::size_t set_index, bool translational, int& steps) {
  st.deferred = false;
  SetOutcome o = combineList(st, set_index, translational, steps);
  if (o == SetOutcome::kCombined && st.deferred) {
    const Tolerance bounded = st.tol;
    st.tol.max_amplification = std::max(bounded.max_amplification, st.tol.angle / kInputRounding);
    st.last_round = true;
    o = combineList(st, set_index, translational, steps);
    st.last_round = false;
    st.tol = bounded;
  }
  return o;
}

void decomposeAll(const Problem& problem, SolveState& st) {
  auto& pending = st.ws.pending;
  pending.clear();
  pending.emplace_back();
  pending.back().clear();
  Decomposition dec;
  for (std::size_t i = 0; i < problem.constraints.size(); ++i) {
    const InputConstraint& c = problem.constraints[i];
    const ConstraintType* type = st.registry.constraintType(c.type);
    if (!type || !type->decompose) {
      setUnhandled(
          st, "constraint " + std::to_string(i) + ": no decomposition for type '" + c.type + "'");
      return;
    }
    // Problems built in code skip the parser: refuse what it would have refused.
    if (!type->accepts_pair(c.fixed.kind, c.mobile.kind)) {
      setUnhandled(st, "constraint " + std::to_string(i) + " is invalid: type '" + c.type +
                           "' does not accept " + toString(c.fixed.kind) + "-" +
                           toString(c.mobile.kind) + " features");
      return;
    }
    // Named for a message, built only when one is needed.
    auto typeItem = [&](const char* call) {
      return "constraint " + std::to_string(i) + ": the " + call + " of constraint type '" +
             c.type + "'" + originNote(type->origin);
    };
    if (type->check) {
      st.ws.problems.clear();
      if (!guarded(
              st, [&] { type->check(c, st.ws.problems, type->context); },
              [&] { return typeItem("value check"); }))
        return;
      if (!st.ws.problems.empty()) {
        setUnhandled(st, "constraint " + std::to_string(i) + " is invalid: " + st.ws.problems[0]);
        return;
      }
    }
    dec.alternatives.clear();
    dec.unhandled = nullptr;
    Feature fixed_W = c.fixed.placed(problem.fixed.pose);
    if (!guarded(
            st, [&] { type->decompose(c, fixed_W, SourceMask{1} << i, dec, type->context); },
            [&] { return typeItem("decomposition"); }))
      return;
    if (dec.unhandled) {
      setUnhandled(st, "constraint " + std::to_string(i) + " (" + c.type + " " +
                           toString(c.fixed.kind) + "-" + toString(c.mobile.kind) +
                           "): " + dec.unhandled);
      return;
    }
    const std::size_t n = pending.size();
    for (std::size_t k = 1; k < dec.alternatives.size(); ++k) {
      if (pending.size() + n > static_cast<std::size_t>(st.options.max_branches)) {
        setUnhandled(st, "more than " + std::to_string(st.options.max_branches) +
                             " alternative constraint sets");
        return;
      }
      for (std::size_t s = 0; s < n; ++s) {
        pending.push_back(pending[s]);
        for (const Fundamental& f : dec.alternatives[k]) pending.back().add(f);
      }
    }
    for (std::size_t s = 0; s < n; ++s)
      for (const Fundamental& f : dec.alternatives[0]) pending[s].add(f);
  }
}

// Branches matched from a `revolve` set describe X' of X = Rot(line, φ) X': unless the matcher
// wrapped them in the turn, they would be wrong poses.
bool allRevolved(const Solution& solution, std::size_t first) {
  for (std::size_t b = first; b < solution.branches.size(); ++b)
    if (solution.branches[b].manifold->kind() != ManifoldKind::kRevolved) return false;
  return true;
}

}  // namespace

namespace detail {

// What would make a branch unusable without any exception to catch later: no manifold, no type
// name, more parameters than a pose has room for (Params: kMaxDof), a parameter without a name
// (the writer copies them). `call` names the method running, should one of them throw. These are
// the cheap calls; the ones that compute (pose, project, describe, ...) cost about as much as
// the whole solve again, so what they throw is caught where they are called (the result writer,
// `solve --collision`), still naming the plugin through Branch::origin.
std::string unusable(const ManifoldHolder& holder, const char*& type, const char*& call) {
  if (!holder) return "a branch without a manifold";
  const Manifold& m = *holder;
  call = "typeName()";
  type = m.typeName();
  if (!type) return "typeName() is null";
  call = "dof()";
  const int dof = m.dof();
  if (dof < 0 || dof > kMaxDof)
    return "dof() is " + std::to_string(dof) + ", outside 0.." + std::to_string(kMaxDof);
  call = "rotationalDof()";
  (void)m.rotationalDof();
  call = "translationalDof()";
  (void)m.translationalDof();
  call = "parameter(i)";
  for (int i = 0; i < dof; ++i)
    if (!m.parameter(i).name) return "parameter(" + std::to_string(i) + ") has no name";
  return "";
}

}  // namespace detail

namespace {

// A plugin's branches are checked here, under the guard, before anything else uses them: a
// manifold that would overrun the writer, or whose cheap methods throw, is an `unhandled` answer
// naming the plugin. Each branch also records its plugin (Branch::origin), for what its other
// methods throw later. Built-in matchers' branches are left alone.
bool checkPluginBranches(SolveState& st, const MatcherInfo& matcher, std::size_t first) {
  if (matcher.origin == "built-in") return true;
  for (std::size_t b = first; b < st.solution.branches.size(); ++b) {
    Branch& branch = st.solution.branches[b];
    branch.origin = matcher.library;
    const char* type = "?";
    const char* call = "";
    std::string problem;
    auto item = [&](bool in_call) {
      return std::string(in_call ? call : "") + (in_call ? " of " : "") + "manifold '" + type +
             "' from matcher '" + matcher.name + "'" + originNote(matcher.origin);
    };
    if (!guarded(
            st, [&] { problem = detail::unusable(branch.manifold, type, call); },
            [&] { return item(true); }))
      return false;
    // A matcher's branch is a closed form: only the numeric stage reports certified ones.
    if (problem.empty() && !branch.exact) problem = "a matcher's branch is not exact";
    if (!problem.empty()) {
      setUnhandled(st, item(false) + " is unusable: " + problem);
      return false;
    }
  }
  return true;
}

bool hasCustomKind(const ConstraintSet& set) {
  for (const Fundamental& f : set.translational)  // (a custom kind is translational)
    if (f.kind == FundamentalKind::kCustom) return true;
  return false;
}

// The set bits of m in increasing order: one step per set bit, not per bit (a solve's redundant
// and conflicting constraints are a few of up to 64).
void listBits(SourceMask m, std::vector<int>& out) {
  for (; m != 0; m &= m - 1) out.push_back(__builtin_ctzll(m));
}

}  // namespace

namespace {

// Combines and matches every set in ws.pending (the list grows as sets branch or defer), then
// turns what happened into the solution's status.
void runPending(SolveState& st) {
  Workspace& ws = st.ws;
  Solution& solution = st.solution;
  SourceMask redundant = ~SourceMask{0};
  bool any_solved_set = false;
  const Tolerance problem_tol = st.tol;
  for (std::size_t s = 0; !st.any_unhandled && s < ws.pending.size(); ++s) {
    if (ws.pending[s].overflow) {
      setUnhandled(st, "too many fundamental constraints");
      break;
    }
    int steps = 0;
    // A set derived under an uncertain rotation has its lengths decided within that too
    // (ConstraintSet::slack).
    st.tol = problem_tol;
    st.tol.length += ws.pending[s].slack;
    SetOutcome o = combineInRounds(st, s, true, steps);
    if (o == SetOutcome::kCombined) o = combineInRounds(st, s, false, steps);
    if (o == SetOutcome::kUnhandled) break;
    if (o == SetOutcome::kInconsistent) continue;
    const ConstraintSet& set = ws.pending[s];
    const std::size_t before = solution.branches.size();
    MatchResult r = MatchResult::kNoMatch;
    // A plugin's kind is for the plugin's matchers only: a built-in one never solves a set while
    // ignoring one.
    const bool custom = hasCustomKind(set);
    BranchSink sink(solution.branches, st.options.max_branches, &ws.pending);
    for (const MatcherInfo& m : st.registry.matchers()) {
      if (custom && m.origin == "built-in") continue;
      MatchContext ctx{set, st.tol, sink};
      const std::size_t had = solution.branches.size();
      if (!guarded(
              st, [&] { r = m.fn(ctx, m.context); },
              [&] { return "matcher '" + m.name + "'" + originNote(m.origin); }))
        break;
      // Whatever it answered: a branch left behind by a matcher that passed is used all the same.
      if (solution.branches.size() > had && !checkPluginBranches(st, m, had)) break;
      if (r == MatchResult::kInconsistent) {
        st.conflicts |= ctx.conflict;
        st.conflict_reason = ctx.reason;
      }
      if (r != MatchResult::kNoMatch) break;
    }
    if (st.any_unhandled) break;  // a matcher threw, or made an unusable branch
    if (r == MatchResult::kNoMatch) {
      // Which input constraints, in the spec's terms, and what might be changed (issue 16); then
      // the combined set itself.
      std::string why = "no solution manifold matches the combined constraints";
      if (st.problem)
        why += " " + detail::explainUnmatched(*st.problem, st.registry, sourcesOf(set)) +
               " Combined set:";
      else
        why += ":";
      setUnhandled(st, why + describeSet(set));
      break;
    }
    if (r == MatchResult::kOverflow) {
      setUnhandled(st, "too many solution branches");
      break;
    }
    if (r == MatchResult::kDeferred) continue;  // its derived sets come later in `pending`
    if (r == MatchResult::kMatched && set.revolve && !allRevolved(solution, before)) {
      setUnhandled(st, "a matcher does not support sets turned about a fixed line");
      break;
    }
    if (r == MatchResult::kMatched) {
      any_solved_set = true;
      redundant &= set.dropped_redundant & ~set.usedSources();
      for (std::size_t b = before; b < solution.branches.size(); ++b)
        solution.branches[b].sources |= set.usedSources();
    }
  }
  st.tol = problem_tol;

  if (st.any_unhandled) {
    solution.status = Status::kUnhandled;
    solution.branches.clear();
    solution.message = st.unhandled;
  } else if (!solution.branches.empty()) {
    solution.status = Status::kSolved;
    if (any_solved_set) listBits(redundant, solution.redundant);
  } else {
    solution.status = Status::kInconsistent;
    listBits(st.conflicts, solution.conflicts);
    solution.message = st.conflict_reason;
  }
}

void prepare(const SolverOptions& options, Workspace& ws, Solution& solution) {
  solution.clear();
  if (ws.pending.capacity() < static_cast<std::size_t>(options.max_branches))
    ws.pending.reserve(static_cast<std::size_t>(options.max_branches));
}

// One attempt: decompose, measure (and with `centre`, centre) the geometry, combine and match;
// the branches are then moved back to the problem's frames. False when a branch's manifold cannot
// be moved back (a plugin's): the caller solves again uncentred. `tol`: the tolerance decided.
bool solveOnce(const Problem& problem, const Registry& registry, const SolverOptions& options,
               bool centre, Workspace& ws, Solution& solution, Tolerance& tol) {
  prepare(options, ws, solution);
  shareRegistryData(registry, solution);
  SolveState st{registry, options, Tolerance(), ws, solution, 0, "", std::string(), false};
  st.problem = &problem;
  std::string why;
  detail::Centring frame;
  if (!options.isValid(&why)) {
    setUnhandled(st, "invalid solver options: " + why);
  } else if (problem.constraints.size() > 64) {
    setUnhandled(st, "more than 64 constraints");
  } else {
    decomposeAll(problem, st);
    frame = detail::centreSets(ws.pending, centre);
    frame.magnitude = std::max(frame.magnitude, detail::placementMagnitude(problem));
    st.tol = detail::toleranceFor(frame, options.length_tolerance, options.angle_tolerance);
    if (const char* range = detail::outOfRange(frame, problem)) {
      setUnhandled(st, range);
    } else {
      const std::string far = detail::tooFarFromOrigin(frame, st.tol, options.length_tolerance);
      if (!far.empty()) setUnhandled(st, far);
    }
  }
  tol = st.tol;
  runPending(st);
  if (!frame.centred || (frame.offset_W.isZero(0.0) && frame.offset_M.isZero(0.0))) return true;
  for (Branch& b : solution.branches) {
    bool moved = false;
    try {  // a plugin's manifold that throws is solved uncentred (and checked there)
      moved = b.manifold.get()->rebase(frame.offset_W, frame.offset_M);
    } catch (...) {
    }
    if (!moved) return false;
  }
  return true;
}

}  // namespace

namespace {

// What a pose is checked against: every input constraint's type and fixed feature in the world,
// looked up and placed once (≤ 64 constraints).
class ConstraintChecks {
 public:
  ConstraintChecks(const Problem& problem, const Registry& registry) : problem_(problem) {
    for (const InputConstraint& c : problem.constraints)
      checks_.push_back({registry.constraintType(c.type), c.fixed.placed(problem.fixed.pose)});
  }
  // The worst violation of an input constraint (in tolerances, by its type's own reading) with
  // the mobile object at X, and which constraint (*which) breaks it most.
  double worstAt(const Isometry3d& X, const Tolerance& tol, std::size_t* which) const {
    double worst = 0.0;
    for (std::size_t i = 0; i < checks_.size(); ++i) {
      const ConstraintType* type = checks_[i].type;
      if (!type || !type->violation) continue;
      const InputConstraint& c = problem_.constraints[i];
      const double v =
          type->violation(c, checks_[i].fixed_W, c.mobile.placed(X), tol, type->context);
      if (!(v <= worst)) worst = v, *which = i;
    }
    return worst;
  }

 private:
  struct Check {
    const ConstraintType* type;
    Feature fixed_W;
  };
  const Problem& problem_;
  FixedVector<Check, 64> checks_;  // (slots not constructed until used)
};

}  // namespace

namespace detail {

// The last check before a solution leaves the solver: one pose of every branch, evaluated against
// every input constraint by its type's own reading of the spec (ConstraintType::violation), not
// by the rules that built the branch. A branch that breaks a constraint by far more than any
// rounding could (10 tolerances) or holds a NaN is a numerical breakdown: the answer is then
// `unhandled`, never a wrong pose.
void checkBranches(const Problem& problem, const Registry& registry, const Tolerance& tol,
                   Solution& solution) {
  if (solution.status != Status::kSolved) return;
  const ConstraintChecks checks(problem, registry);
  for (std::size_t b = 0; b < solution.branches.size(); ++b) {
    const Manifold& m = *solution.branches[b].manifold;
    Isometry3d X;
    Params theta;
    try {                          // a plugin's manifold may throw: the answer then names it
      theta = referenceParams(m);  // a NaN bound makes a NaN parameter
      X = m.pose(theta);
    } catch (const std::exception& e) {
      solution = unhandledAfterThrow(solution, "checking its branches", e.what());
      return;
    }
    bool finite = X.matrix().allFinite();
    for (int i = 0; i < kMaxDof; ++i) finite = finite && !std::isnan(theta[i]);
    std::size_t which = 0;
    const double worst =
        finite ? checks.worstAt(X, tol, &which) : std::numeric_limits<double>::infinity();
    if (worst <= kBreakdownTolerances) continue;
    char why[200];
    if (!finite)
      std::snprintf(why, sizeof why,
                    "numerical breakdown: branch %zu evaluates to non-finite numbers", b);
    else
      std::snprintf(why, sizeof why,
                    "numerical breakdown: branch %zu breaks constraint %zu by %.3g tolerances at "
                    "its reference parameters",
                    b, which, worst);
    solution.branches.clear();
    solution.redundant.clear();
    solution.status = Status::kUnhandled;
    solution.message = why;
    return;
  }
}

}  // namespace detail

namespace {

// The least, over a pattern search of m's parameters from its reference ones, of the worst
// violation of an input constraint (in tolerances): at most 60 rounds of two poses a parameter.
double leastWorstViolation(const Problem& problem, const ConstraintChecks& checks,
                           const Tolerance& tol, const Manifold& m) {
  auto worstAt = [&](const Params& t) {
    try {
      const Isometry3d X = m.pose(t);
      if (!X.matrix().allFinite()) return std::numeric_limits<double>::infinity();
      std::size_t which;
      return checks.worstAt(X, tol, &which);
    } catch (...) {
      return std::numeric_limits<double>::infinity();
    }
  };
  Params best = referenceParams(m);
  double best_v = worstAt(best);
  const int n = m.dof();
  double step[kMaxDof];
  for (int i = 0; i < n; ++i) {
    const Parameter p = m.parameter(i);
    const double width = p.max - p.min;
    step[i] = std::isfinite(width) ? 0.25 * width : std::max(1.0, problem.lengthScale());
  }
  for (int round = 0; round < 60 && best_v > detail::kBreakdownTolerances; ++round) {
    bool moved = false;
    for (int i = 0; i < n; ++i)
      for (double sign : {1.0, -1.0}) {
        Params t = best;
        const Parameter p = m.parameter(i);
        t[i] = std::clamp(t[i] + sign * step[i], p.min, p.max);
        const double v = worstAt(t);
        if (v < best_v) best = t, best_v = v, moved = true;
      }
    if (!moved)
      for (int i = 0; i < n; ++i) step[i] *= 0.5;
  }
  return best_v;
}

// docs/spec.md §6.4: `inconsistent` only when certain. The rules decide within the tolerance plus
// what each derived quantity is known to, and a reading they model too narrowly can find a
// feasible problem inconsistent by a few tolerances: two plane contacts whose planes are 1e-9 rad
// from parallel have their distance read where the problem is centred, while the contacts lie
// ten sizes away, where it differs by 1.6e-9 (a span angle 8e-9 rad off, 5e-9 allowed). The last
// check lets a branch break a constraint by up to 10 tolerances (§6.5): a conflict that the same
// rules no longer find with every tolerance that much wider is in doubt, and `unhandled`.
void doubtNarrowConflict(const Problem& problem, const Registry& registry,
                         const SolverOptions& options, const Tolerance& decided, Workspace& ws,
                         Solution& solution) {
  SolverOptions wide = options;
  wide.length_tolerance *= detail::kBreakdownTolerances;
  wide.angle_tolerance *= detail::kBreakdownTolerances;
  if (!wide.isValid(nullptr)) return;  // tolerances of 1e-3 and more: nothing wider to ask
  // (The workspace's sets are spent: the solution holds what it needs.)
  Solution& widely = ws.widened;
  Tolerance tol;
  if (!solveOnce(problem, registry, wide, true, ws, widely, tol))
    solveOnce(problem, registry, wide, false, ws, widely, tol);
  if (widely.status != Status::kSolved) return;
  // Held to the last check at the tolerance decided: a pose of a branch it would let through
  // (every constraint within 10 tolerances), not one of the wider problem's (a pose 2e-4 rad
  // off where a distance 20 tolerances off is read through acos). Sought along each branch from
  // its reference parameters: near-parallel lines read as parallel meet the second line only
  // where the contacts lie, far from there.
  const ConstraintChecks checks(problem, registry);
  bool near = false;
  for (const Branch& b : widely.branches)
    near = near || leastWorstViolation(problem, checks, decided, *b.manifold) <=
                       detail::kBreakdownTolerances;
  if (!near) return;
  std::string which;
  for (int c : solution.conflicts) which += (which.empty() ? "" : ", ") + std::to_string(c);
  solution.status = Status::kUnhandled;
  solution.message = "undecided: constraints " + which + " conflict by less than " +
                     std::to_string(static_cast<int>(detail::kBreakdownTolerances)) +
                     " tolerances (" + solution.message +
                     "), within what the rules cannot resolve; with the tolerances " +
                     std::to_string(static_cast<int>(detail::kBreakdownTolerances)) +
                     " times wider they are solved";
  solution.conflicts.clear();
  solution.redundant.clear();
  solution.branches.clear();
}

}  // namespace

void solve(const Problem& problem, const Registry& registry, const SolverOptions& options,
           Workspace& ws, Solution& solution) {
  const auto t0 = std::chrono::steady_clock::now();
  Tolerance tol;
  if (!solveOnce(problem, registry, options, true, ws, solution, tol))
    solveOnce(problem, registry, options, false, ws, solution, tol);
  detail::checkBranches(problem, registry, tol, solution);
  if (solution.status == Status::kInconsistent)
    doubtNarrowConflict(problem, registry, options, tol, ws, solution);
  // The rules' closed forms enumerate every branch: what they answered is complete.
  solution.complete =
      solution.status == Status::kSolved || solution.status == Status::kInconsistent;
  solution.isolated_complete = solution.complete;
  // What the rules leave goes to the numeric stage (when one is registered); nothing more runs
  // for a problem they answered.
  if (solution.status == Status::kUnhandled && registry.fallback())
    detail::answerByFallback(problem, registry, options, tol, solution);
  solution.solve_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
}

void solveConstraintSet(const ConstraintSet& set, const Tolerance& tol, const Registry& registry,
                        const SolverOptions& options, Workspace& ws, Solution& solution) {
  prepare(options, ws, solution);
  shareRegistryData(registry, solution);
  SolveState st{registry, options, tol, ws, solution, 0, "", std::string(), false};
  ws.pending.clear();
  ws.pending.push_back(set);
  runPending(st);
  solution.complete =
      solution.status == Status::kSolved || solution.status == Status::kInconsistent;
  solution.isolated_complete = solution.complete;
}

Solution solve(const Problem& problem, const Registry& registry, const SolverOptions& options) {
  Workspace ws;
  Solution s;
  solve(problem, registry, options, ws, s);
  return s;
}

NearestPose nearestOnBranch(const Branch& b, const Isometry3d& X_WM_initial) {
  NearestPose n;
  n.parameters = nearestParams(*b.manifold, X_WM_initial);
  n.pose = b.manifold->pose(n.parameters);
  n.distance = poseDistance(n.pose, X_WM_initial);
  n.global = nearestIsGlobal(*b.manifold, X_WM_initial, n.pose, n.distance);
  return n;
}

Params sampleParameters(const Manifold& m, const Params& centre, double window,
                        std::mt19937_64& rng) {
  Params t{};
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    // The window about the centre moved into the bounds: a centre beyond a finite bound of a
    // half-unbounded parameter (distance ≤ −7e5, centre 0) would otherwise make lo > hi.
    const double c = std::min(std::max(centre[i], p.min), p.max);
    const double lo = std::isfinite(p.min) ? p.min : c - window;
    const double hi = std::isfinite(p.max) ? p.max : c + window;
    t[i] = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return t;
}

}  // namespace relpos
