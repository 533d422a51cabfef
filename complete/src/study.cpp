#include "relpos/complete/study.hpp"

#include <algorithm>
#include <cmath>

#include "relpos/complete/family.hpp"

namespace relpos::complete {
namespace {

// Quaternion product (w, x, y, z) over any scalar.
template <typename S>
void qmul(const S* a, const S* b, S* out) {
  out[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  out[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  out[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  out[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

// R of the unit quaternion q (w first), entry by entry.
template <typename S>
void rotationOf(const S* q, S R[3][3]) {
  const S w = q[0], x = q[1], y = q[2], z = q[3];
  const S one(1.0), two(2.0);
  R[0][0] = one - two * (y * y + z * z), R[0][1] = two * (x * y - w * z),
  R[0][2] = two * (x * z + w * y);
  R[1][0] = two * (x * y + w * z), R[1][1] = one - two * (x * x + z * z),
  R[1][2] = two * (y * z - w * x);
  R[2][0] = two * (x * z - w * y), R[2][1] = two * (y * z + w * x),
  R[2][2] = one - two * (x * x + y * y);
}

// The largest distance of an interval's points from c.
double reach(const Interval& v, double c) { return std::max(v.upper() - c, c - v.lower()); }

// An upper bound of 4 asin(s / 2) (the angle between rotations whose unit quaternions are s
// apart), rounded up.
double angleBound(double s) {
  if (!(s < 2.0)) return kPi;
  return std::min(kPi, std::nextafter(4.0 * std::asin(s / 2.0), 10.0) * (1.0 + 1e-15));
}

}  // namespace

Isometry3d Normalisation::poseOf(const Isometry3d& scaled) const {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = scaled.linear();
  X.translation() = centre_W - scaled.linear() * centre_M + scale * scaled.translation();
  return X;
}

Isometry3d Normalisation::scaledPose(const Isometry3d& X) const {
  Isometry3d S = Isometry3d::Identity();
  S.linear() = X.linear();
  S.translation() = (X.translation() - centre_W + X.linear() * centre_M) / scale;
  return S;
}

Vector8d studyFromPose(const Isometry3d& X, const Eigen::Vector4d& chart) {
  const Quaterniond q(X.linear());
  double e[4] = {q.w(), q.x(), q.y(), q.z()};
  double ce = 0.0;
  for (int i = 0; i < 4; ++i) ce += chart[i] * e[i];
  for (double& z : e) z /= ce;
  const Vector3d& t = X.translation();
  const double tq[4] = {0.0, t.x(), t.y(), t.z()};
  double g[4];
  qmul(tq, e, g);
  Vector8d x;
  for (int i = 0; i < 4; ++i) x[i] = e[i], x[4 + i] = g[i] / 2.0;
  return x;
}

Isometry3d poseFromStudy(const Vector8d& x) {
  const double ee = x.head<4>().squaredNorm();
  const double ec[4] = {x[0], -x[1], -x[2], -x[3]};
  double gec[4];
  qmul(x.data() + 4, ec, gec);
  Isometry3d X = Isometry3d::Identity();
  X.linear() = Quaterniond(x[0], x[1], x[2], x[3]).normalized().toRotationMatrix();
  X.translation() = 2.0 * Vector3d(gec[1], gec[2], gec[3]) / ee;
  return X;
}

bool enclosePose(const Vector8d& x, double r, const Normalisation& n, PoseEnclosure* out) {
  Interval b[8];
  for (int i = 0; i < 8; ++i) b[i] = Interval(x[i] - r, x[i] + r);
  const Interval ee = square(b[0]) + square(b[1]) + square(b[2]) + square(b[3]);
  if (!(ee.lower() > 0.0)) return false;
  const Interval norm = sqrt(ee);
  Interval q[4];
  for (int i = 0; i < 4; ++i) q[i] = b[i] / norm;
  const Interval ec[4] = {b[0], -b[1], -b[2], -b[3]};
  Interval gec[4];
  qmul(b + 4, ec, gec);
  Interval R[3][3];
  rotationOf(q, R);
  out->pose = n.poseOf(poseFromStudy(x));
  const Vector3d& t0 = out->pose.translation();
  double radius = 0.0;
  for (int i = 0; i < 3; ++i) {
    // t = centre_W − R centre_M + scale · 2 vec(g ẽ) / (e·e)
    Interval t = Interval(n.centre_W[i]) + Interval(n.scale) * (Interval(2.0) * gec[i + 1] / ee);
    for (int j = 0; j < 3; ++j) t -= R[i][j] * Interval(n.centre_M[j]);
    radius = std::max(radius, reach(t, t0[i]));
  }
  // The quaternion of the reported rotation, with the sign of the box's (the box does not hold
  // e = 0, so it lies on one side).
  const Quaterniond q0(out->pose.linear());
  double c0[4] = {q0.w(), q0.x(), q0.y(), q0.z()};
  double side = 0.0;
  for (int i = 0; i < 4; ++i) side += c0[i] * x[i];
  if (side < 0.0)
    for (double& c : c0) c = -c;
  Interval dist2(0.0);
  for (int i = 0; i < 4; ++i) dist2 += square(q[i] - Interval(c0[i]));
  out->radius = radius;
  out->angle = angleBound(std::sqrt(dist2.upper()) * (1.0 + 1e-15));
  return std::isfinite(out->radius) && std::isfinite(out->angle);
}

bool encloseLine(const Eigen::Matrix<double, 6, 1>& x, double r, const Normalisation& n,
                 LineEnclosure* out) {
  Interval w[3];
  for (int i = 0; i < 3; ++i) w[i] = Interval(x[i] - r, x[i] + r);
  const Interval ww = square(w[0]) + square(w[1]) + square(w[2]);
  if (!(ww.lower() > 0.0)) return false;
  const Interval norm = sqrt(ww);
  const Vector3d w0 = x.head<3>().normalized();
  Interval dist2(0.0);
  double radius = 0.0;
  out->direction = w0;
  out->point = n.centre_W + n.scale * x.tail<3>();
  for (int i = 0; i < 3; ++i) {
    dist2 += square(w[i] / norm - Interval(w0[i]));
    const Interval p =
        Interval(n.centre_W[i]) + Interval(n.scale) * Interval(x[3 + i] - r, x[3 + i] + r);
    radius = std::max(radius, reach(p, out->point[i]));
  }
  out->radius = radius;
  // Directions s apart are 2 asin(s / 2) apart in angle: half the quaternion bound.
  out->angle = angleBound(std::sqrt(dist2.upper()) * (1.0 + 1e-15)) / 2.0;
  return std::isfinite(out->radius) && std::isfinite(out->angle);
}

}  // namespace relpos::complete
