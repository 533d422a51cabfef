#include "relpos/manifolds/rotation_part.hpp"

#include <algorithm>
#include <cmath>

namespace relpos::manifolds {

const char* toString(RotationKind k) {
  switch (k) {
    case RotationKind::kFixed:
      return "Fixed";
    case RotationKind::kOneParallel:
      return "OneParallel";
    case RotationKind::kOneAngle:
      return "OneAngle";
    case RotationKind::kTwoAngle:
      return "TwoAngle";
    case RotationKind::kFree:
      return "Free";
    case RotationKind::kOneAngleRange:
      return "OneAngleMinMax";
  }
  return "?";
}

namespace {

// The axis w of the rotation by (angle(u_m, u_f) − α) that takes u_m to a vector at angle α from
// u_f (PMF eq. 4, with w = u_m × u_f or any common perpendicular when they are parallel).
Vector3d coneAxis(const Vector3d& u_m, const Vector3d& u_f) {
  const Vector3d w = u_m.cross(u_f);
  const double s = w.norm();
  return s > 1e-12 ? Vector3d(w / s) : anyPerpendicular(u_m);
}

Matrix3d coneBase(const Vector3d& u_m, const Vector3d& u_f, double alpha) {
  return axisAngle(coneAxis(u_m, u_f), angleBetween(u_m, u_f) - alpha);
}

}  // namespace

RotationPart RotationPart::fixed(const Matrix3d& R) {
  RotationPart r;
  r.kind = RotationKind::kFixed;
  // The nearest rotation: R may come from vectors orthogonal only to the angle tolerance.
  r.R0 = Quaterniond(R).normalized().toRotationMatrix();
  return r;
}

RotationPart RotationPart::oneParallel(const Vector3d& u_m, const Vector3d& u_f) {
  RotationPart r;
  r.kind = RotationKind::kOneParallel;
  r.u_m = u_m;
  r.u_f = u_f;
  r.R0 = coneBase(u_m, u_f, 0.0);
  return r;
}

RotationPart RotationPart::oneAngle(const Vector3d& u_m, const Vector3d& u_f, double alpha) {
  RotationPart r;
  r.kind = RotationKind::kOneAngle;
  r.u_m = u_m;
  r.u_f = u_f;
  r.R0 = coneBase(u_m, u_f, alpha);
  return r;
}

RotationPart RotationPart::free() { return RotationPart{}; }

RotationPart RotationPart::oneAngleRange(const Vector3d& u_m, const Vector3d& u_f, double lo,
                                         double hi) {
  RotationPart r;
  r.kind = RotationKind::kOneAngleRange;
  r.u_m = u_m;
  r.u_f = u_f;
  r.alpha_lo = lo;
  r.alpha_hi = hi;
  r.cone_axis = coneAxis(u_m, u_f);
  r.cone_beta = angleBetween(u_m, u_f);
  return r;
}

int RotationPart::dof() const {
  switch (kind) {
    case RotationKind::kFixed:
      return 0;
    case RotationKind::kOneParallel:
      return 1;
    case RotationKind::kOneAngle:
      return 2;
    case RotationKind::kTwoAngle:
      return 1;
    case RotationKind::kFree:
    case RotationKind::kOneAngleRange:
      return 3;
  }
  return 0;
}

Parameter RotationPart::parameter(int i) const {
  Parameter p;
  p.kind = ParamKind::kAngle;
  p.periodic = true;
  switch (kind) {
    case RotationKind::kOneParallel:
      p.name = "phi";
      break;
    case RotationKind::kOneAngle:
      p.name = i == 0 ? "phi" : "theta";
      break;
    case RotationKind::kTwoAngle:
      p.name = "phi";
      p.min = phi_lo;
      p.max = phi_hi;
      p.periodic = phi_periodic;
      break;
    case RotationKind::kFree:
      p.name = i == 0 ? "roll" : (i == 1 ? "pitch" : "yaw");
      if (i == 1) {
        p.min = -kPi / 2;
        p.max = kPi / 2;
        p.periodic = false;
      }
      break;
    case RotationKind::kOneAngleRange:
      p.name = i == 0 ? "phi" : (i == 1 ? "theta" : "alpha");
      if (i == 2) {
        p.min = alpha_lo;
        p.max = alpha_hi;
        p.periodic = false;
      }
      break;
    case RotationKind::kFixed:
      break;
  }
  return p;
}

bool twoAngleTheta(const RotationPart& r, double phi, double* theta) {
  // With R1 = R(u_f, φ) R0, solve (R(u_m, θ) v_m) . g = cos β for g = R1ᵀ v_f:
  // A cos θ + B sin θ = C (App. III-D, written in the mobile frame).
  Matrix3d R1 = axisAngle(r.u_f, phi) * r.R0;
  Vector3d g = R1.transpose() * r.v_f;
  double c = r.u_m.dot(r.v_m);
  Vector3d v_perp = r.v_m - c * r.u_m;
  double A = v_perp.dot(g);
  double B = r.u_m.cross(v_perp).dot(g);
  double C = r.cos_beta - c * r.u_m.dot(g);
  double rho = std::hypot(A, B);
  double ratio = rho > 0 ? C / rho : 2.0;
  bool ok = std::abs(ratio) <= 1.0 + 1e-9;
  *theta = std::atan2(B, A) + r.sign * std::acos(clampUnit(ratio));
  return ok;
}

Matrix3d RotationPart::rotation(const double* t) const {
  switch (kind) {
    case RotationKind::kFixed:
      return R0;
    case RotationKind::kOneParallel:
      return axisAngle(u_f, t[0]) * R0;
    case RotationKind::kOneAngle:
      return axisAngle(u_f, t[0]) * R0 * axisAngle(u_m, t[1]);
    case RotationKind::kTwoAngle: {
      double theta = 0;
      twoAngleTheta(*this, t[0], &theta);
      return axisAngle(u_f, t[0]) * R0 * axisAngle(u_m, theta);
    }
    case RotationKind::kFree:
      return axisAngle(Vector3d::UnitZ(), t[2]) * axisAngle(Vector3d::UnitY(), t[1]) *
             axisAngle(Vector3d::UnitX(), t[0]);
    case RotationKind::kOneAngleRange:
      return spinBase(t) * axisAngle(u_m, t[1]);
  }
  return Matrix3d::Identity();
}

Matrix3d RotationPart::spinBase(const double* t) const {
  if (kind == RotationKind::kOneAngleRange)
    return axisAngle(u_f, t[0]) * axisAngle(cone_axis, cone_beta - t[2]);
  return axisAngle(u_f, t[0]) * R0;  // kOneAngle
}

void RotationPart::project(const Matrix3d& R, double* t) const {
  switch (kind) {
    case RotationKind::kFixed:
      return;
    case RotationKind::kOneParallel:
      t[0] = bestSpinAbout(u_f, R0 * R.transpose());
      return;
    case RotationKind::kOneAngleRange: {
      // α: the angle of R u_m from u_f, clamped to the range; then as for one angle.
      const double a = std::min(alpha_hi, std::max(alpha_lo, angleBetween(R * u_m, u_f)));
      RotationPart fixed_angle = oneAngle(u_m, u_f, a);
      fixed_angle.project(R, t);
      t[2] = a;
      return;
    }
    case RotationKind::kOneAngle: {
      // φ puts R0 u_m at the azimuth (about u_f) of R u_m, then θ is the best spin about u_m.
      Vector3d w0 = R0 * u_m, x = R * u_m;
      Vector3d w0p = w0 - w0.dot(u_f) * u_f, xp = x - x.dot(u_f) * u_f;
      t[0] = (xp.norm() < 1e-12 || w0p.norm() < 1e-12)
                 ? 0.0
                 : std::atan2(w0p.cross(xp).dot(u_f), w0p.dot(xp));
      Matrix3d R1 = axisAngle(u_f, t[0]) * R0;
      t[1] = bestSpinAbout(u_m, R.transpose() * R1);
      return;
    }
    case RotationKind::kTwoAngle: {
      // One-dimensional: the best of a fine deterministic scan, refined by golden section.
      auto cost = [&](double phi) {
        double th[1] = {phi};
        return rotationDistance(rotation(th), R);
      };
      const int n = 64;
      double best = phi_lo, best_c = cost(phi_lo);
      for (int k = 1; k <= n; ++k) {
        double phi = phi_lo + (phi_hi - phi_lo) * k / n;
        double c = cost(phi);
        if (c < best_c) best_c = c, best = phi;
      }
      double h = (phi_hi - phi_lo) / n;
      double a = std::max(phi_lo, best - h), b = std::min(phi_hi, best + h);
      const double g = 0.5 * (std::sqrt(5.0) - 1.0);
      for (int it = 0; it < 60; ++it) {
        double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (cost(x1) < cost(x2))
          b = x2;
        else
          a = x1;
      }
      double m = 0.5 * (a + b);
      t[0] = cost(m) < best_c ? m : best;
      return;
    }
    case RotationKind::kFree: {
      double sp = -R(2, 0);
      t[1] = std::asin(clampUnit(sp));
      if (std::abs(sp) < 1.0 - 1e-12) {
        t[0] = std::atan2(R(2, 1), R(2, 2));
        t[2] = std::atan2(R(1, 0), R(0, 0));
      } else {  // gimbal lock: roll and yaw share one axis; put it all in yaw
        t[0] = 0.0;
        t[2] = std::atan2(-R(0, 1), R(1, 1));
      }
      return;
    }
  }
}

}  // namespace relpos::manifolds
