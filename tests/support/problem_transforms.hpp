#pragma once
#include <algorithm>
// Transforms that leave a problem's answer unchanged up to a known map of poses, for the
// invariance tests (issue 13: "same status, branch count and DOF scaled ×1e-6 and ×1e6 and moved
// 1e6 away"). Each maps the problem (features, poses, values) and a mobile pose of the original
// problem to the corresponding pose of the transformed one, so a known solution stays known.
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"

namespace relpos::test {

// The pure translation by t.
Isometry3d translation(const Vector3d& t);

struct ProblemTransform {
  enum class Kind {
    kIdentity,
    // Every length ×s: feature points, radii, the poses' translations, distance values and
    // bounds (not angles). Solutions: translation ×s, rotation unchanged.
    kScale,
    // The world moved by a rigid G: X_WF' = G·X_WF, X_WM' = G·X_WM (initial and solutions).
    kMoveWorld,
    // The mobile object's frame origin moved: its feature points + o, so X_WM' = X_WM·T(−o) is
    // the same physical placement (initial pose and solutions alike).
    kMoveMobileFrame,
    // The fixed object's frame origin moved: its feature points + o and X_WF' = X_WF·T(−o);
    // the world and so every mobile pose is unchanged.
    kMoveFixedFrame,
  };
  Kind kind = Kind::kIdentity;
  double s = 1.0;
  Isometry3d G = Isometry3d::Identity();
  Vector3d o = Vector3d::Zero();
  std::string label = "identity";

  Problem apply(const Problem& p) const;
  Isometry3d applyToPose(const Isometry3d& X_WM) const;
  // How lengths of the problem scale (s for kScale, else 1).
  double lengthFactor() const { return kind == Kind::kScale ? s : 1.0; }
  // How far the transform moves coordinates (their rounding grows with it).
  double reach() const { return std::max(G.translation().norm(), o.norm()); }

  static ProblemTransform scale(double s);
  static ProblemTransform moveWorld(const Isometry3d& G, const std::string& label);
  static ProblemTransform moveMobileFrame(const Vector3d& o);
  static ProblemTransform moveFixedFrame(const Vector3d& o);
};

// The transforms the invariance test applies: ×1e-6, ×1e6, the world translated 1e6 along a
// fixed direction and also rotated, the mobile and the fixed frame origins moved 1e6.
const std::vector<ProblemTransform>& invarianceTransforms();

}  // namespace relpos::test
