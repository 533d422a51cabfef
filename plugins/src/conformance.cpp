#include "relpos/plugins/conformance.hpp"

#include <cmath>
#include <sstream>

#include "relpos/core/solution.hpp"
#include "relpos/core/solver.hpp"

namespace relpos::plugins {

std::string Report::text() const {
  std::string s;
  for (const auto& f : failures) s += f + "\n";
  return s;
}

std::string poseText(const Isometry3d& X) {
  std::ostringstream os;
  os.precision(17);
  const Quaterniond q(X.linear());
  os << "position [" << X.translation().transpose() << "] quaternion xyzw [" << q.x() << " "
     << q.y() << " " << q.z() << " " << q.w() << "]";
  return os.str();
}

double fundamentalResidual(const Fundamental& f, const Isometry3d& X, const Registry* registry) {
  if (f.kind == FundamentalKind::kCustom) {
    if (!registry || f.custom >= registry->customKinds().size()) return HUGE_VAL;
    const CustomKindInfo& kind = registry->customKinds()[f.custom];
    return kind.residual(f, X, kind.context);
  }
  const Matrix3d R = X.linear();
  const Vector3d T = X.translation();
  const bool pm = f.point_side == Side::kMobile;
  const Vector3d p = pm ? Vector3d(R * f.p + T) : f.p;  // the point, in world
  const Vector3d q = pm ? f.q : Vector3d(R * f.q + T);  // the other element's point
  const Vector3d d = pm ? f.d : Vector3d(R * f.d);      // its direction / normal
  // The measured quantity, then its distance outside [lo, hi] (0 inside).
  double x = 0.0;
  switch (f.kind) {
    case FundamentalKind::kPointPoint:
      x = (p - q).norm();
      break;
    case FundamentalKind::kPointLine:
      x = (p - q).cross(d).norm();
      break;
    case FundamentalKind::kPointPlane:
      x = (p - q).dot(d);
      break;
    case FundamentalKind::kLineLine: {  // skew distance between R·(p, u) + T and (q, d)
      const Vector3d a = R * f.p + T, u = R * f.u;
      const Vector3d n = u.cross(f.d);
      x = n.norm() < 1e-12 ? (a - f.q).cross(f.d).norm() : std::abs((a - f.q).dot(n)) / n.norm();
      break;
    }
    case FundamentalKind::kAngle: {
      const Vector3d u = R * f.p;
      x = std::atan2(u.cross(f.q).norm(), u.dot(f.q));
      break;
    }
    case FundamentalKind::kCustom:
      break;
  }
  return x < f.lo ? f.lo - x : (x > f.hi ? x - f.hi : 0.0);
}

// The solver's sampler (what `samples` in a result draws), about parameters 0.
Params sampleParams(const Manifold& m, std::mt19937_64& rng, double window) {
  return sampleParameters(m, Params{}, window, rng);
}

namespace {
// "[INVARIANT] WHO: WHAT": a failure named by the invariant that broke.
std::string failure(const char* invariant, const std::string& who, const std::string& what) {
  return std::string("[") + invariant + "] " + who + ": " + what;
}
}  // namespace

void checkManifold(const Manifold& m, std::uint64_t seed, Report& report, int samples) {
  auto fail = [&](const char* invariant, const std::string& what) {
    report.failures.push_back(failure(invariant, m.describe(), what));
  };
  std::mt19937_64 rng(seed);
  if (m.dof() < 0 || m.dof() > kMaxDof)
    return fail("dof-in-range", "dof " + std::to_string(m.dof()) + " out of range");
  if (m.rotationalDof() >= 0 && m.rotationalDof() + m.translationalDof() != m.dof())
    fail("dof-split", "rotational + translational DOF differ from dof");
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    if (std::string(p.name).empty())
      fail("parameter-named", "parameter " + std::to_string(i) + " has no name");
    if (!(p.min <= p.max))
      fail("parameter-bounds", std::string("parameter ") + p.name + " has min > max");
    if (p.periodic && p.kind != ParamKind::kAngle)
      fail("periodic-is-angle", std::string(p.name) + ": periodic length");
  }
  const Tolerance tol = Tolerance::forScale(10.0);
  for (int k = 0; k < samples; ++k, ++report.checked) {
    const Params t = sampleParams(m, rng);
    const Isometry3d X = m.pose(t);
    const Matrix3d R = X.linear();
    if ((R.transpose() * R - Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-12 ||
        std::abs(R.determinant() - 1.0) > 1e-12)
      return fail("pose-rigid", "pose is not a rigid motion at sample " + std::to_string(k));
    const Params back = m.project(X);
    for (int i = 0; i < m.dof(); ++i) {
      const Parameter p = m.parameter(i);
      if (!p.periodic && (back[i] < p.min - 1e-9 || back[i] > p.max + 1e-9))
        fail("project-in-bounds",
             std::string("project leaves the bounds of ") + p.name + " at " + poseText(X));
    }
    if (poseDistance(m.pose(back), X) > 1e-7)
      fail("params-round-trip", "project does not return a pose on the manifold: " + poseText(X));
    if (!m.contains(X, tol))
      fail("contains-on-manifold", "contains() is false on the manifold: " + poseText(X));
    // Off the manifold: nearest is never worse than the projection.
    Isometry3d Y = X;
    Y.translation() += Vector3d(0.3, -0.2, 0.4);
    Y.linear() = Eigen::AngleAxisd(0.4, Vector3d(1, 2, 3).normalized()) * Y.linear();
    const Params n = nearestParams(m, Y);
    if (poseDistance(m.pose(n), Y) > poseDistance(m.pose(m.project(Y)), Y) + 1e-12)
      fail("nearest-not-farther", "nearest is worse than the projection from " + poseText(Y));
    // A coupling of at most 1 proves that the nearest pose of a position moved off the manifold
    // keeps its rotation (spec §2.6): no pose of the manifold may be nearer than that one.
    // Drawn over the manifold, and beside the answer (each parameter ± 0.001, 0.01, 0.1).
    if (m.rotationCoupling() <= 1.0) {
      Isometry3d Z = X;
      Z.translation() += Vector3d(0.3, -0.2, 0.4);
      const Params kept = nearestParams(m, Z);
      const double kept_d = poseDistance(m.pose(kept), Z);
      bool nearer = false;
      for (int j = 0; j < 16 && !nearer; ++j)
        nearer = poseDistance(m.pose(sampleParams(m, rng)), Z) < kept_d - 1e-9;
      for (int i = 0; i < m.dof() && !nearer; ++i) {
        const Parameter p = m.parameter(i);
        for (double h : {1e-3, -1e-3, 1e-2, -1e-2, 1e-1, -1e-1}) {
          Params beside = kept;
          beside[i] = p.periodic ? kept[i] + h : std::min(p.max, std::max(p.min, kept[i] + h));
          nearer = nearer || poseDistance(m.pose(beside), Z) < kept_d - 1e-9;
        }
      }
      if (nearer) fail("rotation-coupling", "a pose nearer than the nearest from " + poseText(Z));
    }
    // The search weighs θ as the pose with its closed forms (Manifold::searchDistance).
    Params fast = t, full = t;
    const double weighed = m.searchDistance(Y, &fast);
    const double d = poseDistance(m.poseWithTail(Y, &full), Y);
    if (!(std::abs(weighed - d) <= 1e-9 * (1.0 + d)))
      fail("search-distance", "searchDistance is " + std::to_string(weighed) +
                                  ", the pose with its closed forms " + std::to_string(d) +
                                  " from " + poseText(Y));
  }
}

bool outputImpliesInputs(const Registry& registry, const std::vector<Fundamental>& output,
                         const Fundamental& a, const Fundamental& b, const Tolerance& tol,
                         std::mt19937_64& rng, std::string* bad) {
  ConstraintSet set;
  set.clear();
  for (const Fundamental& f : output) set.add(f);
  Workspace ws;
  Solution s;
  solveConstraintSet(set, tol, registry, SolverOptions(), ws, s);
  if (s.status != Status::kSolved) return false;
  for (const Branch& br : s.branches)
    for (int k = 0; k < 8; ++k) {
      const Isometry3d X = br.manifold->pose(sampleParams(*br.manifold, rng));
      const double ra = fundamentalResidual(a, X, &registry);
      const double rb = fundamentalResidual(b, X, &registry);
      if (ra > 1e-6 || rb > 1e-6) {
        *bad = br.manifold->describe() + " at " + poseText(X) + " residuals " + std::to_string(ra) +
               ", " + std::to_string(rb);
        return true;
      }
    }
  return true;
}

void checkRule(const Registry& registry, const RuleInfo& rule, const Fundamental& a,
               const Fundamental& b, const Tolerance& tol, std::mt19937_64& rng, Report& report,
               const Isometry3d* known) {
  RuleOutput out;
  rule.fn(a, b, tol, out, rule.context);
  const std::string name = rule.firedName(out.fired);
  auto fail = [&](const char* invariant, const std::string& what) {
    report.failures.push_back(failure(invariant, name, what));
  };
  if (out.verdict != RuleVerdict::kNoChange && !rule.cases.empty() && out.fired < 0)
    fail("case-named", "fired without naming its case");
  if (out.verdict == RuleVerdict::kIncompatible && known)
    return fail("satisfiable-not-incompatible",
                std::string("declared a satisfiable pair incompatible: ") + out.reason);
  std::string bad;
  if (out.verdict == RuleVerdict::kRedundantFirst || out.verdict == RuleVerdict::kRedundantSecond) {
    const Fundamental& kept = out.verdict == RuleVerdict::kRedundantFirst ? b : a;
    if (outputImpliesInputs(registry, {kept}, a, b, tol, rng, &bad)) ++report.checked;
    if (!bad.empty())
      fail("redundant-is-implied", "dropped a constraint its partner does not imply: " + bad);
    return;
  }
  if (out.verdict != RuleVerdict::kReplace) return;
  bool some = false;
  for (const auto& alt : out.alternatives) {
    std::vector<Fundamental> fs(alt.begin(), alt.end());
    bad.clear();
    if (outputImpliesInputs(registry, fs, a, b, tol, rng, &bad)) ++report.checked;
    if (!bad.empty())
      fail("replacement-implies-pair",
           "a replacement set admits a pose violating the pair: " + bad);
    if (!known) continue;
    bool all = true;
    for (const Fundamental& f : alt) all = all && fundamentalResidual(f, *known, &registry) < 1e-6;
    some = some || all;
  }
  if (known && !some)
    fail("known-pose-kept", "the known pose satisfies no replacement set: " + poseText(*known));
}

}  // namespace relpos::plugins
