#pragma once
// Small geometric helpers shared by rules and manifolds: the orthonormal basis of two vectors
// (PMF App. I), axis-angle rotations (App. III-B), the rotation between two vector pairs
// (App. III-A), projections and intersections. All inputs are unit vectors where named `u_…`.
#include <Eigen/Geometry>

namespace relpos {

using Eigen::Isometry3d;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

inline constexpr double kPi = 3.14159265358979323846;

// A unit vector perpendicular to u (deterministic choice).
Vector3d anyPerpendicular(const Vector3d& u);

// R(u, phi): rotation by phi about unit axis u.
inline Matrix3d axisAngle(const Vector3d& u, double phi) {
  return Eigen::AngleAxisd(phi, u).toRotationMatrix();
}

// Rotation taking unit vector from onto unit vector to, about their common perpendicular
// (a deterministic perpendicular when they are (anti)parallel).
Matrix3d rotationBetween(const Vector3d& from, const Vector3d& to);

// PMF App. III-A: R(u, v -> r, s) puts u on r and v in the plane of r and s. Requires u, v and
// r, s independent.
Matrix3d rotationPairs(const Vector3d& u, const Vector3d& v, const Vector3d& r, const Vector3d& s);

// Angle between unit vectors, robust near 0 and pi.
double angleBetween(const Vector3d& a, const Vector3d& b);

// Geodesic angle between two rotations.
double rotationDistance(const Matrix3d& a, const Matrix3d& b);

// The φ maximising trace(R(u, φ) M). With M = Xᵀ P (or Q Xᵀ P), the spin R = P R(u, φ) (or
// P R(u, φ) Q) nearest the rotation X: the geodesic angle falls as the trace grows.
double bestSpinAbout(const Vector3d& u, const Matrix3d& M);
// The same, and R(u, φ) itself, built from the cosine and sine the maximisation gives (no sin and
// cos of φ: the nearest-pose search calls this for every pose it weighs).
double bestSpinAbout(const Vector3d& u, const Matrix3d& M, Matrix3d* spin);

// Clamp to [-1, 1] before acos.
inline double clampUnit(double c) { return c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c); }

// Closest point on line (a, unit d) to p.
inline Vector3d projectOnLine(const Vector3d& p, const Vector3d& a, const Vector3d& d) {
  return a + (p - a).dot(d) * d;
}

// Distance between the infinite lines (a1, d1) and (a2, d2) and the foot points on each
// (closest points). Returns false when the lines are parallel (feet then: a1 and its projection).
bool closestPointsOfLines(const Vector3d& a1, const Vector3d& d1, const Vector3d& a2,
                          const Vector3d& d2, double parallel_tol, Vector3d* foot1,
                          Vector3d* foot2);

}  // namespace relpos
