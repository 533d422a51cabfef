// solveSets (stage.hpp): what the polynomial stage does not take — ranges, sets of poses — found
// by local descent from many starts and answered with certified charts (docs/spec.md §8.7).
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "chart_manifold.hpp"
#include "conflict_search.hpp"
#include "dependent_equations.hpp"
#include "implied_equations.hpp"
#include "point_search.hpp"
#include "relpos/complete/stage.hpp"
#include "relpos/core/constraint_text.hpp"
#include "relpos/manifolds/rotation/fixed.hpp"
#include "relpos/manifolds/separable.hpp"
#include "relpos/manifolds/translation/point.hpp"
#include "tangent_pose.hpp"

namespace relpos::complete {
namespace {

using detail::Chart;
using detail::ChartData;
using detail::ChartManifold;
using detail::ConditionSystem;

// The last check's bound (docs/spec.md §6.5).
constexpr double kCheckTolerances = 10.0;
// A chart's first box and the largest it may grow to (normalised coordinates: the quaternion's
// vector part, a turn of about 150° at 4; lengths over the problem's size).
constexpr double kFirstBox = 1e-3;
// When the starts find no pose and the interval search does not prove that none exists: this
// many times as many starts in all.
constexpr int kMoreStarts = 4;
constexpr double kLargestBox = 4.0;
// Isolated poses (0-DOF charts) do not count against StageOptions::max_charts: each costs one
// proof and no growth, and each is a whole component of the set, so the starts go on finding
// them while the answer holds fewer branches than this, shared among the alternatives
// (docs/spec.md §8.7's bound, kept).
// Measured on 600 random 4-constraint problems: of the 97 the numeric stage answered with
// isolated poses, the known pose was among them in 73 with at most two charts, in 90 with this.
constexpr std::size_t kMostBranches = 8;
// When every pose found is isolated: this many times as many starts in all. Measured on 1,200
// random 4- and 5-constraint problems with ranges (seed 31): of the 324 the stage answered with
// isolated poses, the known pose was among them in 312 with the first starts, in 319 with
// twice as many (four times: no more); those answers took about 40 % longer.
constexpr int kIsolatedStarts = 2;

// Grows the chart from the first box, or from smaller ones when the base is that close to a
// range's edge or to where the equations' Jacobian turns singular: a small chart is still a
// certified piece of the set.
// `hint`: a box the charts of the same set before proved in every coordinate (0: none), tried
// first — the growth from there costs a few proofs, not the dozen from the first box; and such
// a chart grows only in every coordinate alike (the first chart of the set has reached along
// each).
bool grown(Chart& chart, double hint) {
  if (hint > kFirstBox && detail::growChart(chart, hint, kLargestBox, false)) return true;
  double first = kFirstBox;
  for (int k = 0; k < 4; ++k, first *= 0.1)  // 1e-3 down to 1e-6
    if (detail::growChart(chart, first, kLargestBox)) return true;
  return false;
}

// The smallest half-width of a chart's box, over its tangent coordinates.
double smallestRadius(const Chart& chart) {
  double r = kLargestBox;
  for (int j = 0; j < chart.d; ++j) r = std::min(r, chart.radius[j]);
  return r;
}

// Whether pose (R, t) is already a pose of one of `charts`, inside its box.
bool covered(const std::vector<std::shared_ptr<const ChartData>>& charts, const Matrix3d& R,
             const Vector3d& t) {
  for (const auto& c : charts) {
    const std::array<double, 6> th = detail::chartProject(c->chart, R, t);
    Matrix3d R2;
    Vector3d t2;
    detail::chartPose(c->chart, th, &R2, &t2);
    if ((t2 - t).norm() + (R2 - R).norm() < 1e-7) return true;
  }
  return false;
}

// How far the plane offsets and cosines a chart dropped as constants may be off on it (0: none
// dropped): what an implied equation that follows from them may be off by besides its own.
struct DroppedSlack {
  double cosine = 0.0, plane = 0.0;
};

// The chart of `s` about pose (R, t) finished on s's equations to rounding: its proof's slice,
// and what the proof says of equations dropped from s, are then their own, not the descent's
// residual over the conditioning (measured: a far-placed copy's base, 2e-10 off, proved a
// dropped cosine only to 2.4e-9).
bool polishedChart(const ConditionSystem& s, Matrix3d R, Vector3d t, Chart* chart) {
  detail::polishPose(s.equations, &R, &t);
  return detail::makeChart(s, R, t, chart);
}

// The chart at pose (R, t): of all the equations, or where they are dependent, of those
// independent there, the others constants on the piece (dependent_equations.hpp) proven to hold
// (within half the tolerance, and the slack the descent allows for the rounding of the
// coordinates as placed) at the chart's exact base, and so on its whole piece.
bool chartAt(const ConditionSystem& s, const Matrix3d& R, const Vector3d& t, double length_tol,
             double angle_tol, const detail::EquationSlack& slack, Chart* chart,
             DroppedSlack* earlier) {
  *earlier = DroppedSlack();
  if (polishedChart(s, R, t, chart)) return true;
  ConditionSystem reduced;
  std::vector<detail::Condition> dropped;
  if (!detail::reduceDependent(s, R, t, &reduced, &dropped) || !polishedChart(reduced, R, t, chart))
    return false;
  // half the tolerance, in each condition's units
  std::vector<double> within;
  for (const detail::Condition& c : dropped) {
    // Moved 1e6 away, the coordinates' rounding alone leaves a constant said twice 1e-10 apart
    // at the exact base (measured: one of 300 random problems lost its chart in a far-placed
    // copy); slack is a hundredth of the tolerance where that rounding is less.
    // A skew condition's |n| read at the base, less a margin far beyond how far the exact base
    // is. What is constant on the piece is the distance |h|/|n| (with the direction pinned |n|
    // is too; a skew across a pinned direction, kept off parallel, turns with |n| but keeps that
    // distance), so the base's bound on it holds on the whole piece.
    within.push_back(
        detail::toleranceAt(c, R, 0.5 * length_tol + slack.length, 0.5 * angle_tol + slack.angle));
  }
  std::vector<double> proven;
  if (!detail::holdAtExactBase(*chart, dropped, within, &proven)) return false;
  // A dropped plane offset or cosine (what an implied equation may follow from) is off on the
  // whole piece by what it is off at the exact base: a constant there.
  for (std::size_t i = 0; i < dropped.size(); ++i) {
    if (dropped[i].kind == detail::ConditionKind::kCosine)
      earlier->cosine = std::max(earlier->cosine, proven[i]);
    else if (dropped[i].kind == detail::ConditionKind::kPointPlane)
      earlier->plane = std::max(earlier->plane, proven[i]);
  }
  return true;
}

// Whether the equations dropped as implied hold within the tolerance over the whole chart: its
// poses' mobile points reach no further than its base's translation plus its box and slice.
bool impliedHold(const Chart& chart, const std::vector<detail::ImpliedEquation>& implied,
                 const DroppedSlack& earlier, double length_tol, double angle_tol) {
  double box = chart.m * chart.slice * chart.slice;
  for (int j = 0; j < chart.d; ++j) box += chart.radius[j] * chart.radius[j];
  for (const detail::ImpliedEquation& e : implied) {
    const bool plane = e.condition.kind == detail::ConditionKind::kPointPlane;
    const double reach = detail::vec(e.condition.p).norm() + chart.t0.norm() + std::sqrt(box);
    const double off = detail::impliedViolation(e, reach, plane ? earlier.plane : earlier.cosine);
    if (!(off <= detail::toleranceInUnits(e.condition, length_tol, angle_tol))) return false;
  }
  return true;
}

// The chart's poses at its centre and at both ends of every axis of its box, checked against
// every input constraint (the proof says they hold; this is the solver's own check of it).
bool verified(const ChartManifold& m, const Problem& problem, const Registry& registry,
              const Tolerance& tol) {
  Params theta{};
  if (!(detail::worstViolation(problem, registry, tol, m.pose(theta)) <= kCheckTolerances))
    return false;
  for (int j = 0; j < m.dof(); ++j)
    for (double s : {-1.0, 1.0}) {
      Params th{};
      th[j] = s * m.parameter(j).max;
      if (!(detail::worstViolation(problem, registry, tol, m.pose(th)) <= kCheckTolerances))
        return false;
    }
  return true;
}

// Deterministic start poses (normalised): the mobile object's own, then seeded random ones,
// turned and placed relative to it (a rotation R_init·R, a position R_init·u about the fixed
// features' centre), so that the same problem in a moved or turned world starts from the same
// poses relative to its geometry.
std::vector<std::pair<Matrix3d, Vector3d>> startPoses(const Problem& problem,
                                                      const ConditionSystem& s, int count) {
  std::vector<std::pair<Matrix3d, Vector3d>> starts;
  const Isometry3d& X = problem.mobile.pose;
  const Matrix3d R_init = X.linear();
  // the object's own pose, unless far beyond its task (then its rotation, about the centre)
  const Vector3d t_init = s.frame.scaledPose(X).translation();
  starts.emplace_back(R_init, t_init.norm() <= 1e3 ? t_init : Vector3d::Zero());
  std::mt19937_64 rng(0x5e75u);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  while (static_cast<int>(starts.size()) < count) {
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    const Vector3d u(uniform(rng), uniform(rng), uniform(rng));
    starts.emplace_back(R_init * q.toRotationMatrix(), R_init * u);
  }
  return starts;
}

// What to change when the poses found were singular: the constraints dependent there.
std::string singularHint(const Problem& problem, const Registry& registry, SourceMask dependent) {
  if (dependent == 0) return "";
  return " (at them " + describeConstraints(problem, registry, dependent) +
         " restrict one freedom twice, or meet tangentially: stating it once — dropping the "
         "constraint the others imply, or a range instead of a tangency — lets the stage chart "
         "the set)";
}

}  // namespace

bool solveSets(const Problem& problem, const Registry& registry, const Tolerance& tol,
               Solution& solution, const StageOptions& options) {
  if (!(detail::largestMagnitude(problem) <= 1e100)) {
    solution.message = "coordinates or values beyond 1e100 (or not numbers): scale the problem";
    return false;
  }
  std::vector<ConditionSystem> systems;
  std::string why;
  if (!detail::buildConditionSystems(problem, registry, &systems, &why)) {
    solution.message = why;
    return false;
  }
  const std::size_t n = problem.constraints.size();
  const SourceMask sources = n >= 64 ? ~SourceMask{0} : (SourceMask{1} << n) - 1;
  std::vector<Branch> branches;
  int points = 0;
  SourceMask dependent = 0;  // the constraints dependent at a pose found where no chart was
  // Per alternative: the charts' equations without those the others imply (the proof of
  // inconsistency below keeps them all), and its charts so far.
  struct Alternative {
    ConditionSystem s;
    std::vector<detail::ImpliedEquation> implied;
    detail::EquationSlack slack;
    std::vector<std::shared_ptr<const ChartData>> charts;
    std::size_t sets = 0;  // charts of positive dimension (max_charts counts only these)
    std::vector<std::pair<Matrix3d, Vector3d>> touching;  // tangentPose's, normalised
    std::size_t answered() const { return charts.size() + touching.size(); }
  };
  std::vector<Alternative> alternatives(systems.size());
  for (std::size_t a = 0; a < systems.size(); ++a) {
    Alternative& alt = alternatives[a];
    alt.s = systems[a];
    detail::dropImpliedEquations(&alt.s, tol.length / alt.s.frame.scale, tol.angle, &alt.implied);
    // equations said twice may be apart by the rounding of a far-placed problem, or of the
    // values a task's author computed: a pose meeting them to a hundredth of the tolerance is
    // found (the chart's proof then takes the exact one; measured, a random problem whose
    // equations said twice were 2.2e-12 apart, over the thousandth allowed before, went
    // unanswered where its copies moved 1e6 were charted) — and never less than two ulps of the
    // coordinates as placed: a hundredth of a tolerance that is itself 64 ulps (a problem placed
    // 1e6 from its origin) is below their rounding
    alt.slack.length = std::max({alt.slack.length, 1e-2 * tol.length / alt.s.frame.scale,
                                 2.0 * std::numeric_limits<double>::epsilon() *
                                     detail::largestMagnitude(problem) / alt.s.frame.scale});
    alt.slack.angle = std::max(alt.slack.angle, 1e-2 * tol.angle);
    // ... and the rounding of far-placed positions, where equations couple them to the turn,
    // leaves angles apart by as much (normalised lengths are about 1: a turn by δ moves a point
    // by about δ). Measured, the world moved 1e6: a point-plane offset left 1.4e-11 from its
    // value (allowed 7e-12), a cosine 1.9e-12 (allowed 1e-12); every start declined, where the
    // problem as given was solved.
    alt.slack.angle = std::max(alt.slack.angle, alt.slack.length);
  }
  const std::size_t quota = std::max<std::size_t>(
      1, (static_cast<std::size_t>(std::max(options.max_charts, 0)) + systems.size() - 1) /
             std::max<std::size_t>(systems.size(), 1));
  // Each alternative's share of the answer's branches, isolated poses included.
  const std::size_t share =
      std::max(quota, kMostBranches / std::max<std::size_t>(systems.size(), 1));
  // Where the equations are dependent at the pose found because two constraints touch there:
  // the touching pose, proven (tangent_pose.hpp), an isolated pose of the set — answered once,
  // checked against every input constraint.
  auto touchingPose = [&](Alternative& alt, const Matrix3d& R, const Vector3d& t, double length_tol,
                          double angle_tol) {
    detail::TangentPose tp;
    std::vector<detail::Condition> implied;
    for (const detail::ImpliedEquation& e : alt.implied) implied.push_back(e.condition);
    if (!detail::tangentPose(alt.s, implied, R, t, length_tol, angle_tol, &tp)) return false;
    for (const auto& [R2, t2] : alt.touching)
      if ((t2 - tp.t).norm() + (R2 - tp.R).norm() < 1e-7) return true;
    Isometry3d scaled = Isometry3d::Identity();
    scaled.linear() = tp.R;
    scaled.translation() = tp.t;
    const Isometry3d X = alt.s.frame.poseOf(scaled);
    if (!(detail::worstViolation(problem, registry, tol, X) <= kCheckTolerances)) return false;
    alt.touching.emplace_back(tp.R, tp.t);
    Branch b;
    b.manifold.emplace<manifolds::SeparableManifold>(
        manifolds::rotation::Fixed(X.linear()),
        manifolds::translation::Point(
            Fundamental::pointPoint(Vector3d::Zero(), X.translation(), 0.0, sources)));
    b.sources = sources;
    b.exact = false;
    // The box's half-width w in each local coordinate: the turn within 2·√3·w, the position
    // within √3·w (normalised) and the turn's reach from the rotation's centre to the origin.
    const double turn = 2.0 * std::sqrt(3.0) * tp.radius;
    b.certified = {
        std::sqrt(3.0) * tp.radius * alt.s.frame.scale + turn * alt.s.frame.centre_M.norm(), turn};
    branches.push_back(std::move(b));
    return true;
  };
  // The descents from starts [first, last) of every alternative (the same starts for each,
  // whatever the constraints' order), a chart about each pose found that no chart holds yet.
  auto search = [&](int first, int last) {
    for (Alternative& alt : alternatives) {
      const ConditionSystem& s = alt.s;
      const double length_tol = tol.length / s.frame.scale;
      const auto starts = startPoses(problem, s, last);
      for (int k = first; k < last && alt.sets < quota && alt.answered() < share; ++k) {
        auto [R, t] = starts[static_cast<std::size_t>(k)];
        if (!detail::findPoint(s, &R, &t, alt.slack)) continue;
        ++points;
        if (covered(alt.charts, R, t)) continue;
        auto data = std::make_shared<ChartData>();
        DroppedSlack earlier;
        const double hint =
            alt.charts.empty() ? 0.0 : 0.5 * smallestRadius(alt.charts.front()->chart);
        // no chart at a singular pose (or one so nearly singular that no proof holds)
        if (!chartAt(s, R, t, length_tol, tol.angle, alt.slack, &data->chart, &earlier) ||
            !grown(data->chart, hint)) {
          if (!touchingPose(alt, R, t, length_tol, tol.angle))
            dependent |= detail::dependentSources(s, R, t);
          continue;
        }
        if (!impliedHold(data->chart, alt.implied, earlier, length_tol, tol.angle)) continue;
        data->frame = s.frame;
        const ChartManifold m(data);
        if (!verified(m, problem, registry, tol)) continue;
        alt.charts.push_back(data);
        if (data->chart.d > 0) ++alt.sets;
        Branch b;
        b.manifold.emplace<ChartManifold>(m);
        b.sources = sources;
        b.exact = false;
        const double spread = data->chart.slice * std::sqrt(static_cast<double>(data->chart.m));
        b.certified = {spread * s.frame.scale, 2.0 * spread};
        branches.push_back(std::move(b));
      }
    }
  };
  search(0, options.set_starts);
  // Only isolated poses found: each a whole component of the set, so the starts go on (as many
  // again) for the ones they missed.
  bool isolated_only = !branches.empty();
  for (const Alternative& alt : alternatives) isolated_only = isolated_only && alt.sets == 0;
  if (isolated_only) search(options.set_starts, kIsolatedStarts * options.set_starts);
  std::string unproven;
  if (branches.empty() && points == 0) {
    // No pose found: perhaps there is none. Proven only by the interval search of every pose.
    const detail::ConflictProof proof =
        detail::proveConflict(systems, n, tol, options.exclusion_boxes);
    unproven = proof.why;
    // Not proven: the descents may have missed (a set far from every start, a narrow one).
    // More starts, before answering that nothing was found.
    if (!proof.proven) search(options.set_starts, kMoreStarts * options.set_starts);
    if (proof.proven) {
      solution.branches.clear();
      solution.status = Status::kInconsistent;
      solution.complete = solution.isolated_complete = true;
      solution.conflicts.clear();
      for (std::size_t i = 0; i < n; ++i)
        if (proof.conflicts & (SourceMask{1} << (i % 64)))
          solution.conflicts.push_back(static_cast<int>(i));
      solution.message =
          "no pose meets these constraints together: an interval search of every "
          "pose in reach excludes them all (" +
          std::to_string(proof.boxes) + " boxes)";
      return true;
    }
  }
  if (branches.empty()) {
    solution.message =
        points == 0 ? "no pose found by descent from " +
                          std::to_string(kMoreStarts * options.set_starts *
                                         static_cast<int>(systems.size())) +
                          " starts, and not proven inconsistent: " + unproven
                    : "the " + std::to_string(points) +
                          " poses found are singular points of the constraints or on a range's "
                          "edge: no chart proven" +
                          singularHint(problem, registry, dependent);
    return false;
  }
  solution.branches = std::move(branches);
  solution.status = Status::kSolved;
  solution.complete = false;
  solution.isolated_complete = false;
  solution.conflicts.clear();
  solution.message.clear();
  return true;
}

}  // namespace relpos::complete
