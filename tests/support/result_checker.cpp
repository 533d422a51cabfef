#include "result_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <vector>

#include "evaluator.hpp"
#include "problem_transforms.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/report/evaluate.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

Vector3d centroid(const ObjectSpec& o) {
  Vector3d c = Vector3d::Zero();
  for (const NamedFeature& f : o.features) c += f.feature.point;
  return o.features.empty() ? c : Vector3d(c / static_cast<double>(o.features.size()));
}

bool finite(const Params& t, int dof) {
  for (int i = 0; i < dof; ++i)
    if (!std::isfinite(t[i])) return false;
  return true;
}

// How far X's rotation is from orthonormal (the evaluator normalises directions, so a sheared or
// scaled rotation would otherwise pass unnoticed); a reflection counts as far.
double rigidityError(const Isometry3d& X) {
  const Matrix3d R = X.linear();
  if (!(R.determinant() > 0.0)) return 1.0;
  return (R.transpose() * R - Matrix3d::Identity()).cwiseAbs().maxCoeff();
}
bool rigid(const Isometry3d& X) { return X.matrix().allFinite() && rigidityError(X) <= 1e-9; }

std::string paramsText(const Params& t, int dof) {
  std::ostringstream os;
  os.precision(17);
  os << "[";
  for (int i = 0; i < dof; ++i) os << (i ? ", " : "") << t[i];
  os << "]";
  return os.str();
}

// Parameters within the bounds; unbounded ones within ±window (lengths) or ±π (others) of centre.
Params drawParams(const Manifold& m, const Params& centre, double window, std::mt19937_64& rng) {
  Params t{};
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    const double w = p.kind == ParamKind::kLength ? window : kPi;
    double lo = std::isfinite(p.min) ? p.min : centre[i] - w;
    double hi = std::isfinite(p.max) ? p.max : centre[i] + w;
    if (std::isfinite(p.min) && !std::isfinite(p.max)) hi = std::max(hi, lo + w);
    if (!std::isfinite(p.min) && std::isfinite(p.max)) lo = std::min(lo, hi - w);
    t[i] = lo == hi ? lo : std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return t;
}

using json = nlohmann::json;

// Every null in the result line must be one docs/spec.md §2 allows: an unbounded parameter's bound
// (the manifold's bound is ±inf, not NaN), the DOF split of a mixed branch, `best` without
// branches. Anything else is a NaN or inf that the writer turned into null.
void checkNulls(const json& j, const std::string& path, const std::vector<std::string>& keys,
                const Solution& s, std::string* bad) {
  if (!bad->empty()) return;
  if (j.is_null()) {
    const std::size_t n = keys.size();
    bool allowed = false;
    if (n == 1 && keys[0] == "best") allowed = s.branches.empty();
    if (n == 3 && keys[0] == "branches" &&
        (keys[2] == "rotational_dof" || keys[2] == "translational_dof")) {
      const Manifold& m = *s.branches[std::stoul(keys[1])].manifold;
      allowed = m.rotationalDof() < 0;
    }
    if (n == 5 && keys[0] == "branches" && keys[2] == "parameters" &&
        (keys[4] == "min" || keys[4] == "max")) {
      const Parameter par = s.branches[std::stoul(keys[1])].manifold->parameter(std::stoi(keys[3]));
      const double v = keys[4] == "min" ? par.min : par.max;
      allowed = std::isinf(v);
    }
    if (!allowed) *bad = "null (a NaN or inf) at " + path;
    return;
  }
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    *bad = "non-finite number at " + path;
    return;
  }
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      std::vector<std::string> k = keys;
      k.push_back(it.key());
      checkNulls(it.value(), path + "." + it.key(), k, s, bad);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      std::vector<std::string> k = keys;
      k.push_back(std::to_string(i));
      checkNulls(j[i], path + "[" + std::to_string(i) + "]", k, s, bad);
    }
  }
}

}  // namespace

double problemSize(const Problem& p) {
  const double s = problemExtent(p);
  return s > 0.0 ? s : 1.0;
}

double problemExtent(const Problem& p) {
  // Every feature point where the spec places it: fixed ones by the fixed pose, mobile ones by
  // the initial pose.
  // (magnitude: the largest coordinates placing them involves, whose rounding they carry.)
  std::vector<Vector3d> points;
  double magnitude = 0.0;
  for (const ObjectSpec* o : {&p.fixed, &p.mobile})
    for (const NamedFeature& f : o->features) {
      points.push_back(o->pose * f.feature.point);
      magnitude = std::max(magnitude, o->pose.translation().norm() + f.feature.point.norm());
    }
  Vector3d c = Vector3d::Zero();
  for (const Vector3d& q : points) c += q;
  if (!points.empty()) c /= static_cast<double>(points.size());
  double s = 0.0;
  for (const Vector3d& q : points) s = std::max(s, (q - c).norm());
  // Points that coincide but for the rounding of placing them have no extent (a spread of 1e-16
  // would make every comparison relative to it; seed offset 7394: a point placed at the origin
  // from coordinates of 1e6 carried 3e-16 of it).
  if (s <= 1e3 * std::numeric_limits<double>::epsilon() * magnitude) s = 0.0;
  for (const InputConstraint& cn : p.constraints) {
    s = std::max({s, cn.fixed.radius, cn.mobile.radius});
    if (cn.type == "angle") continue;
    for (double v : {cn.value, cn.min, cn.max})
      if (std::isfinite(v)) s = std::max(s, std::abs(v));
  }
  return s;
}

RelativeEvaluator::RelativeEvaluator(const Problem& p, double size) : size_(size) {
  const Vector3d centre = p.fixed.pose * centroid(p.fixed);
  to_normalised_ = translation(-centre);
  normalised_ = ProblemTransform::scale(1.0 / size)
                    .apply(ProblemTransform::moveWorld(to_normalised_, "centred").apply(p));
  mobile_centroid_ = centroid(p.mobile);
}

double RelativeEvaluator::worst(const Isometry3d& X_WM, int* which) const {
  Isometry3d X = to_normalised_ * X_WM;
  X.translation() /= size_;
  return worstViolation(normalised_, X, which);
}

double RelativeEvaluator::poseGap(const Isometry3d& A, const Isometry3d& B) const {
  return (A * mobile_centroid_ - B * mobile_centroid_).norm() / size_ +
         rotationDistance(A.linear(), B.linear());
}

std::string CheckReport::summary() const {
  std::string out;
  for (const std::string* s :
       {&non_finite, &non_rigid, &violating, &known_lost, &bad_json, &false_global})
    if (!s->empty()) out += "  " + *s + "\n";
  return out;
}

std::string firedRules(const Solution& s) {
  std::string out;
  for (const char* r : s.ruleNames()) out += (out.empty() ? "" : ", ") + std::string(r);
  return out.empty() ? "(no rule)" : out;
}

CheckReport checkSolution(const Problem& p, const Solution& s, const CheckOptions& opt) {
  CheckReport rep;
  const double size = opt.size > 0.0 ? opt.size : problemSize(p);
  const RelativeEvaluator eval(p, size);
  std::mt19937_64 rng(opt.seed);
  // `sample` ≥ 0: that sample; kNearest, kNearestKnown: the nearest poses (text only on failure:
  // a check runs thousands of poses).
  constexpr int kNearest = -1, kNearestKnown = -2;
  auto pose = [&](const Isometry3d& X, const Params& t, int dof, int sample, std::size_t b) {
    auto what = [&] {
      return sample == kNearest        ? std::string("nearest (to the initial pose)")
             : sample == kNearestKnown ? std::string("nearest to the known pose")
                                       : "sample " + std::to_string(sample);
    };
    if (!X.matrix().allFinite() || !finite(t, dof)) {
      if (rep.non_finite.empty())
        rep.non_finite = "branch " + std::to_string(b) + " " + what() +
                         ": not finite: parameters " + paramsText(t, dof) + " -> " + poseText(X);
      return;
    }
    if (!rigid(X)) {
      if (rep.non_rigid.empty()) {
        std::ostringstream os;
        os.precision(3);
        os << "branch " << b << " " << what()
           << ": not a rotation, |RtR - I| = " << rigidityError(X) << ", at parameters "
           << paramsText(t, dof) << ": " << poseText(X);
        rep.non_rigid = os.str();
      }
      return;
    }
    int which = -1;
    const double v = eval.worst(X, &which);
    if (v > rep.worst_violation) {
      rep.worst_violation = v;
      if (v > opt.violation_tolerance) {
        std::ostringstream os;
        os.precision(3);
        os << "branch " << b << " " << what() << " violates constraint " << which << " by " << v
           << " (relative to size " << size << ") at parameters " << paramsText(t, dof) << ": "
           << poseText(X);
        rep.violating = os.str();
      }
    }
  };
  // The result line as written (with two samples per branch): every number finite. Its nearest
  // poses are the ones checked below (nearestOnBranch is the costliest part of a check: it is
  // not run twice for the same pose).
  ReportOptions ro;
  ro.samples = 2;
  ro.window = size;
  ro.seed = opt.seed;
  std::string line;
  writeResultLine(p, s, ro, line);
  json doc;
  try {
    doc = json::parse(line);
    checkNulls(doc, "", {}, s, &rep.bad_json);
  } catch (const std::exception& e) {
    rep.bad_json = std::string("result line does not parse: ") + e.what();
  }
  // The written nearest parameters of branch b, when they are all there (a null is reported).
  auto writtenNearest = [&](std::size_t b, int dof, Params* t) {
    if (!doc.is_object() || !doc.contains("branches") || b >= doc["branches"].size()) return false;
    const json& ps = doc["branches"][b]["nearest"]["parameters"];
    if (!ps.is_array() || static_cast<int>(ps.size()) != dof) return false;
    for (int i = 0; i < dof; ++i) {
      if (!ps[i].is_number()) return false;
      (*t)[i] = ps[i].get<double>();
    }
    return true;
  };
  for (std::size_t b = 0; b < s.branches.size(); ++b) {
    const Manifold& m = *s.branches[b].manifold;
    const int dof = m.dof();
    if (dof < 0 || dof > kMaxDof) {
      rep.non_finite = "branch " + std::to_string(b) + ": dof " + std::to_string(dof);
      continue;
    }
    bool bounds_ok = true;
    for (int i = 0; i < dof; ++i) {
      const Parameter par = m.parameter(i);
      if (std::isnan(par.min) || std::isnan(par.max) || !(par.min <= par.max)) {
        bounds_ok = false;
        rep.non_finite = "branch " + std::to_string(b) + " parameter " + par.name + ": bounds [" +
                         std::to_string(par.min) + ", " + std::to_string(par.max) + "]";
      }
    }
    // Samples of a branch without valid bounds would be drawn from nowhere in particular (and
    // blamed as violations): the bounds are the failure.
    if (!bounds_ok) continue;
    Params centre{};
    if (!writtenNearest(b, dof, &centre)) {
      const NearestPose initial = nearestOnBranch(s.branches[b], p.mobile.pose);
      centre = initial.parameters;
    }
    pose(m.pose(centre), centre, dof, kNearest, b);
    if (opt.known) {
      const NearestPose k = nearestOnBranch(s.branches[b], *opt.known);
      pose(k.pose, k.parameters, dof, kNearestKnown, b);
      if (k.pose.matrix().allFinite())
        rep.known_gap = std::min(rep.known_gap, eval.poseGap(k.pose, *opt.known));
      const Isometry3d projected = m.pose(m.project(*opt.known));
      if (projected.matrix().allFinite())
        rep.known_projection_gap =
            std::min(rep.known_projection_gap, eval.poseGap(projected, *opt.known));
      centre = k.parameters;
    }
    if (!finite(centre, dof)) centre = Params{};
    // A nearest pose written as proven the branch's nearest (`nearest_global`): no pose of the
    // branch drawn here is nearer the initial pose (beyond the rounding of the distances).
    const json* written = nullptr;
    if (doc.is_object() && doc.contains("branches") && b < doc["branches"].size())
      written = &doc["branches"][b];
    const bool global = written && written->value("nearest_global", false) &&
                        (*written)["nearest"]["distance"].is_number();
    const double global_d = global ? (*written)["nearest"]["distance"].get<double>() : 0.0;
    const double slack =
        1e-9 * (1.0 + global_d) + 1e-14 * (1.0 + p.mobile.pose.translation().norm());
    auto nearerThanGlobal = [&](const Isometry3d& X, const std::string& what) {
      if (!global || !rep.false_global.empty() || !X.matrix().allFinite()) return;
      const double d = poseDistance(X, p.mobile.pose);
      if (d < global_d - slack) {
        std::ostringstream os;
        os.precision(17);
        os << "branch " << b << " says its nearest pose (distance " << global_d
           << ") is proven the nearest, but " << what << " is at " << d << ": " << poseText(X);
        rep.false_global = os.str();
      }
    };
    if (opt.known) nearerThanGlobal(m.pose(centre), "the pose nearest the known pose");
    for (int k = 0; k < opt.samples_per_branch; ++k) {
      const Params t = drawParams(m, centre, 3.0 * size, rng);
      const Isometry3d X = m.pose(t);
      pose(X, t, dof, k, b);
      nearerThanGlobal(X, "sample " + std::to_string(k));
    }
  }
  if (opt.known && !s.branches.empty() && !(rep.known_gap <= opt.known_tolerance)) {
    std::ostringstream os;
    os.precision(3);
    os << "the known pose is on no branch: nearest gap " << rep.known_gap << " > "
       << opt.known_tolerance << " (relative; through the projection: " << rep.known_projection_gap
       << ")";
    rep.known_lost = os.str();
  }
  return rep;
}

}  // namespace relpos::test
