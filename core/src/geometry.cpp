#include "relpos/core/geometry.hpp"

#include <cmath>

namespace relpos {

Vector3d anyPerpendicular(const Vector3d& u) {
  // Cross with the world axis least aligned with u: well conditioned and deterministic.
  Vector3d a = u.cwiseAbs();
  Vector3d axis = (a.x() <= a.y() && a.x() <= a.z()) ? Vector3d::UnitX()
                  : (a.y() <= a.z())                 ? Vector3d::UnitY()
                                                     : Vector3d::UnitZ();
  return u.cross(axis).normalized();
}

Matrix3d rotationBetween(const Vector3d& from, const Vector3d& to) {
  Vector3d w = from.cross(to);
  double s = w.norm();
  double c = from.dot(to);
  if (s < 1e-15) {
    if (c > 0) return Matrix3d::Identity();
    return axisAngle(anyPerpendicular(from), kPi);
  }
  return axisAngle(w / s, std::atan2(s, c));
}

namespace {
// PMF App. I: orthonormal basis {u, v_u, w} of two independent unit vectors, as matrix columns.
// v's part across u is taken to full precision (nearly parallel vectors leave little of it), and
// the columns are made orthonormal to rounding: a rotation built from them stays a rotation.
Matrix3d basisOf(const Vector3d& u, const Vector3d& v) {
  const Vector3d w = u.cross(perpendicularPart(v, u)).normalized();
  Matrix3d B;
  B.col(0) = u;
  B.col(1) = w.cross(u);
  B.col(2) = w;
  return B;
}
}  // namespace

Matrix3d rotationPairs(const Vector3d& u, const Vector3d& v, const Vector3d& r, const Vector3d& s) {
  return basisOf(r, s) * basisOf(u, v).transpose();
}

namespace {
// v − u or v + u, whichever is the short one.
Vector3d shortDifference(const Vector3d& v, const Vector3d& u) {
  return u.dot(v) >= 0.0 ? Vector3d(v - u) : Vector3d(v + u);
}
}  // namespace

Vector3d accurateCross(const Vector3d& u, const Vector3d& v) {
  return u.cross(shortDifference(v, u));  // u × (v ∓ u) = u × v
}

Vector3d perpendicularPart(const Vector3d& v, const Vector3d& u) {
  const Vector3d e = shortDifference(v, u);
  return e - e.dot(u) * u;  // (v ∓ u) − ((v ∓ u)·u) u = v − (v·u) u
}

Vector3d pointWherePlanesMeet(const Vector3d& a, const Vector3d& n_a, const Vector3d& b,
                              const Vector3d& n_b) {
  const Vector3d w = perpendicularPart(n_b, n_a);
  // (a + λ w − b)·n_b = 0. w·n_b, not |w|²: the two differ by the normals' own rounding, which
  // |w|² ~ angle² would magnify.
  return a + ((b - a).dot(n_b) / w.dot(n_b)) * w;
}

double angleBetween(const Vector3d& a, const Vector3d& b) {
  // The sine from the short difference (accurateCross): a plain a × b of vectors 1e-9 apart keeps
  // only 7 of its digits, enough to put an angle of 1.0000001e-9 on either side of a 1e-9
  // tolerance.
  return std::atan2(accurateCross(a, b).norm(), a.dot(b));
}

namespace {
// The angle of D = aᵀb from its trace (cos) and its skew part (*sin_axis, sin times the axis):
// atan2 keeps full precision near 0 and π, without the quaternion and axis Eigen::AngleAxisd
// would also compute.
double angleOf(const Matrix3d& a, const Matrix3d& b, Vector3d* sin_axis) {
  const Matrix3d D = a.transpose() * b;
  *sin_axis = 0.5 * Vector3d(D(2, 1) - D(1, 2), D(0, 2) - D(2, 0), D(1, 0) - D(0, 1));
  return std::atan2(sin_axis->norm(), 0.5 * (D.trace() - 1.0));
}
}  // namespace

double rotationDistance(const Matrix3d& a, const Matrix3d& b) {
  Vector3d sin_axis;
  return angleOf(a, b, &sin_axis);
}

Vector3d rotationVector(const Matrix3d& a, const Matrix3d& b, double* angle) {
  Vector3d sin_axis;
  *angle = angleOf(a, b, &sin_axis);
  const double s = sin_axis.norm();
  return s > 0.0 ? Vector3d(sin_axis * (*angle / s)) : Vector3d::Zero();
}

Vector3d rotationVector(const Matrix3d& a, const Matrix3d& b) {
  double angle;
  return rotationVector(a, b, &angle);
}

namespace {
// [u]×, the matrix of v ↦ u × v.
Matrix3d crossMatrix(const Vector3d& u) {
  Matrix3d K;
  K << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
  return K;
}

// trace(R(u, φ) M) = cos φ (tr M − uᵀMu) + sin φ tr([u]× M) + uᵀMu: the coefficients of cos φ
// (a) and sin φ (b).
void spinCoefficients(const Vector3d& u, const Matrix3d& M, double* a, double* b) {
  *a = M.trace() - u.dot(M * u);
  *b = (crossMatrix(u) * M).trace();
}
}  // namespace

double bestSpinAbout(const Vector3d& u, const Matrix3d& M) {
  double a, b;
  spinCoefficients(u, M, &a, &b);
  return std::atan2(b, a);
}

double bestSpinAbout(const Vector3d& u, const Matrix3d& M, Matrix3d* spin) {
  double a, b;
  spinCoefficients(u, M, &a, &b);
  const double r = std::sqrt(a * a + b * b);  // |a|, |b| ≤ 3: no overflow to guard against
  // r = 0: every spin is as good; φ = atan2(0, 0) = 0, as above.
  const double c = r > 0.0 ? a / r : 1.0, s = r > 0.0 ? b / r : 0.0;
  // Rodrigues: R = c I + s [u]× + (1 − c) u uᵀ.
  *spin = c * Matrix3d::Identity() + s * crossMatrix(u) + (1.0 - c) * (u * u.transpose());
  return std::atan2(b, a);
}

bool closestPointsOfLines(const Vector3d& a1, const Vector3d& d1, const Vector3d& a2,
                          const Vector3d& d2, double parallel_tol, Vector3d* foot1,
                          Vector3d* foot2) {
  const Vector3d n = accurateCross(d1, d2);
  const double s = n.norm();
  if (!(s > parallel_tol)) {
    *foot1 = a1;
    *foot2 = projectOnLine(a1, a2, d2);
    return false;
  }
  const Vector3d m = n / s;  // the common perpendicular's direction
  const Vector3d r = a2 - a1;
  // a1 + t1 d1 + h m = a2 + t2 d2; crossing with d2 and dotting with m: t1 = r·(d2 × m) / |n|.
  // The separation h = r·m is read off directly (it is well conditioned), so foot2 − foot1 is
  // exactly the perpendicular, not the difference of two feet each uncertain along the lines.
  const double t1 = r.dot(d2.cross(m)) / s;
  *foot1 = a1 + t1 * d1;
  *foot2 = *foot1 + r.dot(m) * m;
  return true;
}

}  // namespace relpos
