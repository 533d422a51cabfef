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

// u × v and v − (v·u) u for unit vectors u, v, to full relative precision also when they are
// nearly (anti)parallel: computed from the difference v ∓ u, which is exact or nearly so, instead
// of from products of nearly equal numbers (whose rounding, ~1e-16, is all that is left of a
// cross product 1e-8 long). Nearly parallel lines and planes are where the rules decide
// "meet" or "do not meet".
Vector3d accurateCross(const Vector3d& u, const Vector3d& v);
Vector3d perpendicularPart(const Vector3d& v, const Vector3d& u);

// The point of the line where the planes (a, unit n_a) and (b, unit n_b) meet that lies in a's
// plane across from a (a + λ·(n_b's part ⊥ n_a)), for planes that are not parallel. Accurate to
// the rounding of the coordinates divided by the planes' angle, which is as well as the line is
// determined at all (the textbook solve divides by 1 − (n_a·n_b)², which keeps ~1e-16 absolute).
Vector3d pointWherePlanesMeet(const Vector3d& a, const Vector3d& n_a, const Vector3d& b,
                              const Vector3d& n_b);

// Angle between unit vectors, to full relative precision near 0 and pi.
double angleBetween(const Vector3d& a, const Vector3d& b);

// Geodesic angle between two rotations.
double rotationDistance(const Matrix3d& a, const Matrix3d& b);
// The rotation taking a to b in a's frame as its axis times its angle (aᵀb = exp([v]×)): its norm
// is rotationDistance(a, b); smooth where the angle is small (the nearest-pose search's residual).
Vector3d rotationVector(const Matrix3d& a, const Matrix3d& b);
// The same, and *angle = rotationDistance(a, b) (which the vector's norm loses at exactly π).
Vector3d rotationVector(const Matrix3d& a, const Matrix3d& b, double* angle);

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

// The feet of the common perpendicular of the infinite lines (a1, unit d1) and (a2, unit d2):
// foot2 − foot1 is the perpendicular itself, whose length is the distance between the lines to
// the rounding of the coordinates, however close to parallel they are (the feet's positions
// along the lines are as uncertain as the lines' crossing is: ~ulp/angle). Returns false when the
// lines are parallel within parallel_tol (feet then: a1 and its projection).
bool closestPointsOfLines(const Vector3d& a1, const Vector3d& d1, const Vector3d& a2,
                          const Vector3d& d2, double parallel_tol, Vector3d* foot1,
                          Vector3d* foot2);

}  // namespace relpos
