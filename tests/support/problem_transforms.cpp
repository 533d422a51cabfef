#include "problem_transforms.hpp"

#include <cstdio>

namespace relpos::test {
// (Declared in problem_transforms.hpp.)
Isometry3d translation(const Vector3d& t) {
  Isometry3d T = Isometry3d::Identity();
  T.translation() = t;
  return T;
}

namespace {

// Applies f to every feature of the object and to the copies the constraints hold of them.
template <typename F>
void eachFeature(Problem& p, bool fixed, F&& f) {
  for (NamedFeature& nf : (fixed ? p.fixed : p.mobile).features) f(nf.feature);
  for (InputConstraint& c : p.constraints) f(fixed ? c.fixed : c.mobile);
}

}  // namespace

ProblemTransform ProblemTransform::scale(double s) {
  ProblemTransform t;
  t.kind = Kind::kScale;
  t.s = s;
  char buf[32];
  std::snprintf(buf, sizeof buf, "scaled x%g", s);
  t.label = buf;
  return t;
}

ProblemTransform ProblemTransform::moveWorld(const Isometry3d& G, const std::string& label) {
  ProblemTransform t;
  t.kind = Kind::kMoveWorld;
  t.G = G;
  t.label = label;
  return t;
}

ProblemTransform ProblemTransform::moveMobileFrame(const Vector3d& o) {
  ProblemTransform t;
  t.kind = Kind::kMoveMobileFrame;
  t.o = o;
  t.label = "mobile frame origin moved 1e6";
  return t;
}

ProblemTransform ProblemTransform::moveFixedFrame(const Vector3d& o) {
  ProblemTransform t;
  t.kind = Kind::kMoveFixedFrame;
  t.o = o;
  t.label = "fixed frame origin moved 1e6";
  return t;
}

Problem ProblemTransform::apply(const Problem& in) const {
  Problem p = in;
  switch (kind) {
    case Kind::kIdentity:
      break;
    case Kind::kScale: {
      for (bool fixed : {true, false})
        eachFeature(p, fixed, [&](Feature& f) {
          f.point *= s;
          f.radius *= s;
        });
      p.fixed.pose.translation() *= s;
      p.mobile.pose.translation() *= s;
      for (ObjectSpec& o : p.obstacles) o.pose.translation() *= s;
      for (InputConstraint& c : p.constraints) {
        if (c.type == "angle") continue;  // the only built-in type whose value is not a length
        c.value *= s;
        c.min *= s;  // ±inf stay ±inf (s > 0)
        c.max *= s;
      }
      break;
    }
    case Kind::kMoveWorld:
      p.fixed.pose = G * p.fixed.pose;
      p.mobile.pose = G * p.mobile.pose;
      for (ObjectSpec& o : p.obstacles) o.pose = G * o.pose;
      break;
    case Kind::kMoveMobileFrame:
      eachFeature(p, false, [&](Feature& f) { f.point += o; });
      p.mobile.pose = p.mobile.pose * translation(-o);
      break;
    case Kind::kMoveFixedFrame:
      eachFeature(p, true, [&](Feature& f) { f.point += o; });
      p.fixed.pose = p.fixed.pose * translation(-o);
      break;
  }
  return p;
}

Isometry3d ProblemTransform::applyToPose(const Isometry3d& X) const {
  switch (kind) {
    case Kind::kScale: {
      Isometry3d Y = X;
      Y.translation() *= s;
      return Y;
    }
    case Kind::kMoveWorld:
      return G * X;
    case Kind::kMoveMobileFrame:
      return X * translation(-o);
    case Kind::kIdentity:
    case Kind::kMoveFixedFrame:
      break;
  }
  return X;
}

const std::vector<ProblemTransform>& invarianceTransforms() {
  static const std::vector<ProblemTransform> all = [] {
    // A direction with no zero component, so that no coordinate stays small.
    const Vector3d far = 1e6 * Vector3d(2, -3, 6) / 7.0;
    Isometry3d shift = translation(far);
    Isometry3d turn = shift;
    turn.linear() = Eigen::AngleAxisd(2.0, Vector3d(1, 4, -8) / 9.0).toRotationMatrix();
    return std::vector<ProblemTransform>{
        ProblemTransform::scale(1e-6),
        ProblemTransform::scale(1e6),
        ProblemTransform::moveWorld(shift, "world moved 1e6"),
        ProblemTransform::moveWorld(turn, "world moved 1e6 and rotated"),
        ProblemTransform::moveMobileFrame(1e6 * Vector3d(-4, 4, 7) / 9.0),
        ProblemTransform::moveFixedFrame(1e6 * Vector3d(6, 2, -3) / 7.0),
    };
  }();
  return all;
}

}  // namespace relpos::test
