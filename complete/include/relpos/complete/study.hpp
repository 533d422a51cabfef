#pragma once
// From a root of an encoding to a pose (or a line) of the problem as given, and back: the Study
// parameters of a pose, the scaled and centred frames the encodings work in, and the enclosure
// of the pose over a certified root's box, in the problem's units (issue 15).
#include <Eigen/Core>

#include "relpos/core/geometry.hpp"

namespace relpos::complete {

using Vector8d = Eigen::Matrix<double, 8, 1>;

// The frames the encodings see: fixed (world) coordinates about centre_W, mobile ones about
// centre_M, lengths divided by scale. A pose X' there is the pose T(centre_W) S X' S⁻¹ T(−centre_M)
// of the problem (S: the scaling), i.e. R the same and t = centre_W − R centre_M + scale · t'.
struct Normalisation {
  Vector3d centre_W = Vector3d::Zero();
  Vector3d centre_M = Vector3d::Zero();
  double scale = 1.0;

  Vector3d fixedPoint(const Vector3d& p_W) const { return (p_W - centre_W) / scale; }
  Vector3d mobilePoint(const Vector3d& p_M) const { return (p_M - centre_M) / scale; }
  double length(double d) const { return d / scale; }
  Isometry3d poseOf(const Isometry3d& scaled) const;
  Isometry3d scaledPose(const Isometry3d& X) const;
};

// (e, g) of X with the chart c·e = 1: e = q / (c·q) for X's unit quaternion q (w first; the sign
// that makes c·q positive), g = t e / 2. Requires c·q ≠ 0.
Vector8d studyFromPose(const Isometry3d& X, const Eigen::Vector4d& chart);
// R = e · ẽ / (e·e), t = 2 vec(g ẽ) / (e·e), for any real e ≠ 0.
Isometry3d poseFromStudy(const Vector8d& x);

// A certified real root's pose in the problem's units, and how far the true pose may be from it:
// `radius` bounds the position error (each coordinate), `angle` the rotation's (radians), both
// from interval enclosures of R and t over the box x ± r.
struct PoseEnclosure {
  Isometry3d pose = Isometry3d::Identity();
  double radius = 0.0;
  double angle = 0.0;
};
// False when the box holds e = 0 (no pose).
bool enclosePose(const Vector8d& x, double r, const Normalisation& n, PoseEnclosure* out);

// A line root x = (w, q') of LineFamily: the world line through scale·q' + centre_W along w
// (normalised), with the same error bounds (`radius` the point's, `angle` the direction's).
struct LineEnclosure {
  Vector3d point = Vector3d::Zero();
  Vector3d direction = Vector3d::UnitZ();
  double radius = 0.0;
  double angle = 0.0;
};
bool encloseLine(const Eigen::Matrix<double, 6, 1>& x, double r, const Normalisation& n,
                 LineEnclosure* out);

}  // namespace relpos::complete
