#include "random_problems.hpp"

#include <cmath>

namespace relpos::test {

using K = FeatureKind;
constexpr double kPiT = 3.14159265358979323846;

Vector3d Rng::unit() {
  Vector3d v;
  do {
    v = Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
  } while (v.norm() < 0.1 || v.norm() > 1.0);
  return v.normalized();
}

Vector3d Rng::point(double half) {
  return Vector3d(uniform(-half, half), uniform(-half, half), uniform(-half, half));
}

Vector3d Rng::unitOrAxis(bool axis) {
  if (!axis) return unit();
  Vector3d v = Vector3d::Zero();
  v[integer(0, 2)] = integer(0, 1) ? 1.0 : -1.0;
  return v;
}

Vector3d Rng::pointOrGrid(bool grid, double half) {
  if (!grid) return point(half);
  return Vector3d(integer(-2, 2), integer(-2, 2), integer(-2, 2));
}

Isometry3d Rng::pose(bool axis_aligned) {
  Isometry3d X = Isometry3d::Identity();
  if (axis_aligned) {
    // A rotation by a multiple of 90° about an axis: integer matrices.
    X.linear() = Eigen::AngleAxisd(kPiT / 2 * integer(0, 3), unitOrAxis(true)).toRotationMatrix();
    X.linear() = X.linear().array().round().matrix();
    X.translation() = pointOrGrid(true);
  } else {
    X.linear() = Eigen::AngleAxisd(uniform(0, kPiT), unit()).toRotationMatrix();
    X.translation() = point();
  }
  return X;
}

Vector3d Rng::perpendicular(const Vector3d& u) {
  Vector3d v = unit();
  v -= v.dot(u) * u;
  if (v.norm() < 1e-3) return perpendicular(u);
  return v.normalized();
}

const std::vector<SingleKind>& singleKinds() {
  using O = Orientation;
  static const std::vector<SingleKind> k = {
      {"distance", K::kPoint, K::kPoint, O::kAligned, 5, 1, "distance point-point"},
      {"distance", K::kLine, K::kPoint, O::kAligned, 5, 1, "distance line(f)-point(m)"},
      {"distance", K::kPoint, K::kLine, O::kAligned, 5, 1, "distance point(f)-line(m)"},
      {"distance", K::kPlane, K::kPoint, O::kAligned, 5, 1, "distance plane(f)-point(m)"},
      {"distance", K::kPoint, K::kPlane, O::kAligned, 5, 1, "distance point(f)-plane(m)"},
      {"distance", K::kLine, K::kLine, O::kAligned, 3, 1, "distance line-line aligned"},
      {"distance", K::kLine, K::kLine, O::kOpposed, 3, 1, "distance line-line opposed"},
      {"distance", K::kPlane, K::kLine, O::kAligned, 4, 1, "distance plane(f)-line(m)"},
      {"distance", K::kLine, K::kPlane, O::kAligned, 4, 1, "distance line(f)-plane(m)"},
      {"distance", K::kPlane, K::kPlane, O::kAligned, 3, 1, "distance plane-plane"},
      {"distance", K::kPlane, K::kPlane, O::kEither, 3, 2, "distance plane-plane either"},
      {"coincident", K::kPoint, K::kPoint, O::kAligned, 3, 1, "coincident point-point"},
      {"coincident", K::kLine, K::kPoint, O::kAligned, 4, 1, "coincident line(f)-point(m)"},
      {"coincident", K::kPoint, K::kLine, O::kAligned, 4, 1, "coincident point(f)-line(m)"},
      {"coincident", K::kPlane, K::kPoint, O::kAligned, 5, 1, "coincident plane(f)-point(m)"},
      {"coincident", K::kPoint, K::kPlane, O::kAligned, 5, 1, "coincident point(f)-plane(m)"},
      {"coincident", K::kLine, K::kLine, O::kAligned, 2, 1, "coincident line-line"},
      {"coincident", K::kLine, K::kLine, O::kEither, 2, 2, "coincident line-line either"},
      {"coincident", K::kPlane, K::kLine, O::kAligned, 4, 1, "coincident plane(f)-line(m)"},
      {"coincident", K::kLine, K::kPlane, O::kAligned, 4, 1, "coincident line(f)-plane(m)"},
      {"coincident", K::kPlane, K::kPlane, O::kOpposed, 3, 1, "coincident plane-plane opposed"},
      {"coincident", K::kCylinder, K::kPoint, O::kAligned, 5, 1, "coincident cylinder(f)-point(m)"},
      {"coincident", K::kPoint, K::kCylinder, O::kAligned, 5, 1, "coincident point(f)-cylinder(m)"},
      {"angle", K::kLine, K::kLine, O::kAligned, 5, 1, "angle line-line"},
      {"angle", K::kPlane, K::kLine, O::kAligned, 5, 1, "angle plane(f)-line(m)"},
      {"angle", K::kLine, K::kPlane, O::kAligned, 5, 1, "angle line(f)-plane(m)"},
      {"angle", K::kPlane, K::kPlane, O::kAligned, 5, 1, "angle plane-plane"},
      {"parallel", K::kLine, K::kLine, O::kAligned, 4, 1, "parallel line-line"},
      {"parallel", K::kPlane, K::kPlane, O::kOpposed, 4, 1, "parallel plane-plane opposed"},
      {"parallel", K::kPlane, K::kLine, O::kAligned, 5, 1, "parallel plane(f)-line(m)"},
      {"perpendicular", K::kLine, K::kLine, O::kAligned, 5, 1, "perpendicular line-line"},
      {"perpendicular", K::kPlane, K::kPlane, O::kAligned, 5, 1, "perpendicular plane-plane"},
      {"perpendicular", K::kPlane, K::kLine, O::kAligned, 4, 1, "perpendicular plane(f)-line(m)"},
      {"perpendicular", K::kLine, K::kPlane, O::kOpposed, 4, 1, "perpendicular line(f)-plane(m)"},
      {"tangent", K::kPlane, K::kCylinder, O::kAligned, 4, 1, "tangent plane(f)-cylinder(m)"},
      {"tangent", K::kCylinder, K::kPlane, O::kOpposed, 4, 1, "tangent cylinder(f)-plane(m)"},
      {"tangent", K::kCylinder, K::kCylinder, O::kAligned, 3, 2, "tangent cylinder-cylinder"},
      {"skew-distance", K::kLine, K::kLine, O::kAligned, 5, 1, "skew distance line-line"},
      {"tangent", K::kCylinder, K::kLine, O::kAligned, 5, 1, "tangent cylinder(f)-line(m)"},
      {"tangent", K::kLine, K::kCylinder, O::kAligned, 5, 1, "tangent line(f)-cylinder(m)"},
  };
  return k;
}

KnownProblem emptyKnownProblem(Rng& rng, bool axis_aligned) {
  KnownProblem kp;
  kp.problem.name = "random";
  kp.problem.fixed.name = "base";
  kp.problem.mobile.name = "part";
  kp.problem.fixed.pose = rng.pose(axis_aligned);
  kp.problem.mobile.pose = rng.pose(axis_aligned);  // the initial pose: anywhere
  kp.X_WM_star = rng.pose(axis_aligned);
  return kp;
}

namespace {

Feature randomFeature(K kind, Rng& rng, bool grid) {
  Vector3d p = rng.pointOrGrid(grid), d = rng.unitOrAxis(grid);
  switch (kind) {
    case K::kPoint:
      return Feature::makePoint(p);
    case K::kLine:
      return Feature::makeLine(p, d);
    case K::kPlane:
      return Feature::makePlane(p, d);
    case K::kCylinder:
      return Feature::makeCylinder(p, d, grid ? rng.integer(1, 2) : rng.uniform(0.1, 1.0));
  }
  return Feature::makePoint(p);
}

// A direction at angle a from u (a rotation of u about a random perpendicular axis).
Vector3d atAngle(const Vector3d& u, double a, Rng& rng) {
  return Eigen::AngleAxisd(a, rng.perpendicular(u)) * u;
}

double orientationSign(Orientation o, Rng& rng) {
  if (o == Orientation::kOpposed) return -1.0;
  if (o == Orientation::kEither) return rng.integer(0, 1) ? 1.0 : -1.0;
  return 1.0;
}

}  // namespace

void addConstraint(KnownProblem& kp, const SingleKind& kind, Rng& rng, bool grid,
                   const NamedFeature* reuse) {
  Problem& pb = kp.problem;
  const Isometry3d& X_WF = pb.fixed.pose;
  const Isometry3d& X = kp.X_WM_star;
  const std::string tag = std::to_string(pb.constraints.size());
  // The mobile feature, then its world placement at the known pose.
  const bool reusing = reuse && reuse->feature.kind == kind.mobile;
  Feature m = reusing ? reuse->feature : randomFeature(kind.mobile, rng, grid);
  const Feature mW = m.placed(X);
  Feature fW = randomFeature(kind.fixed, rng, grid);  // world frame, adjusted below
  InputConstraint c;
  c.type = kind.type;
  c.orientation = kind.orientation;
  c.has_value = true;
  const std::string t = kind.type;
  const double sgn = orientationSign(kind.orientation, rng);
  const Vector3d in_plane_jitter = rng.point(1.0);
  auto valueDistance = [&](bool is_signed) {
    // Unsigned distances stay positive: a zero distance is a coincidence, with other DOF.
    return grid ? double(rng.integer(is_signed ? -2 : 1, 2))
                : rng.uniform(is_signed ? -1.5 : 0.05, 1.5);
  };
  double v = 0.0;
  if (t == "distance" || t == "coincident") {
    const bool dist = t == "distance";
    const bool fixed_point = kind.fixed == K::kPoint, mobile_point = kind.mobile == K::kPoint;
    if (fixed_point && mobile_point) {
      v = dist ? valueDistance(false) : 0.0;
      fW.point = mW.point + v * rng.unitOrAxis(grid);
    } else if (mobile_point || fixed_point) {
      const Feature& P = mobile_point ? mW : fW;  // the point (world)
      const K xk = mobile_point ? kind.fixed : kind.mobile;
      if (xk == K::kPlane)
        v = dist ? valueDistance(true) : 0.0;
      else if (xk == K::kCylinder)
        v = 0.0;
      else
        v = dist ? valueDistance(false) : 0.0;
      if (mobile_point) {
        // Place the fixed line/plane/cylinder relative to the mobile point.
        const Vector3d d = fW.direction;
        if (xk == K::kPlane) {
          fW.point = P.point - v * d + (in_plane_jitter - in_plane_jitter.dot(d) * d);
        } else {
          const double r = xk == K::kCylinder ? fW.radius : v;
          fW.point = P.point + r * rng.perpendicular(d) + rng.uniform(-1, 1) * d;
        }
      } else {
        // Place the fixed point relative to the mobile line/plane/cylinder.
        const Vector3d d = mW.direction;
        if (xk == K::kPlane) {
          fW.point = mW.point + v * d + (in_plane_jitter - in_plane_jitter.dot(d) * d);
        } else {
          const double r = xk == K::kCylinder ? mW.radius : v;
          fW.point = mW.point + r * rng.perpendicular(d) + rng.uniform(-1, 1) * d;
        }
      }
    } else if (kind.fixed == K::kLine && kind.mobile == K::kLine) {
      v = dist ? valueDistance(false) : 0.0;
      fW.direction = sgn * mW.direction;
      fW.point = mW.point + v * rng.perpendicular(mW.direction) + rng.uniform(-1, 1) * mW.direction;
    } else if (kind.fixed == K::kPlane && kind.mobile == K::kPlane) {
      v = dist ? valueDistance(true) : 0.0;
      fW.direction = sgn * mW.direction;
      const Vector3d n = fW.direction;
      fW.point = mW.point - v * n + (in_plane_jitter - in_plane_jitter.dot(n) * n);
    } else {  // line–plane
      v = dist ? valueDistance(true) : 0.0;
      const bool plane_fixed = kind.fixed == K::kPlane;
      if (plane_fixed) {
        fW.direction = rng.perpendicular(mW.direction);
        const Vector3d n = fW.direction;
        fW.point = mW.point - v * n + (in_plane_jitter - in_plane_jitter.dot(n) * n);
      } else {
        fW.direction = rng.perpendicular(mW.direction);  // line ⊥ plane normal
        const Vector3d n = mW.direction;
        fW.point = mW.point + v * n + (in_plane_jitter - in_plane_jitter.dot(n) * n);
      }
    }
  } else if (t == "angle") {
    const bool line_plane = kind.fixed != kind.mobile;
    if (line_plane) {
      v = grid ? kPiT / 4 * rng.integer(-1, 1) : rng.uniform(-1.4, 1.4);
      // asin(d·n) = v: angle between them π/2 − v.
      fW.direction = atAngle(mW.direction, kPiT / 2 - v, rng);
    } else {
      v = grid ? kPiT / 4 * rng.integer(1, 3) : rng.uniform(0.05, kPiT - 0.05);
      fW.direction = atAngle(mW.direction, v, rng);
    }
  } else if (t == "parallel") {
    if (kind.fixed != kind.mobile)
      fW.direction = rng.perpendicular(mW.direction);
    else
      fW.direction = sgn * mW.direction;
  } else if (t == "perpendicular") {
    if (kind.fixed != kind.mobile)
      fW.direction = sgn * mW.direction;
    else
      fW.direction = rng.perpendicular(mW.direction);
  } else if (t == "skew-distance" ||
             (t == "tangent" && (kind.fixed == K::kLine || kind.mobile == K::kLine))) {
    // Fixed line (or axis) at distance v from the mobile line (or axis) along their common
    // perpendicular.
    v = t == "skew-distance" ? valueDistance(false)
                             : (kind.fixed == K::kCylinder ? fW.radius : mW.radius);
    // Not parallel: near parallel lines the skew distance jumps (tilting one line within their
    // common plane makes them meet), so rounding noise would break the known solution.
    do {
      fW.direction = rng.unitOrAxis(grid);
    } while (mW.direction.cross(fW.direction).norm() < 0.1);
    const Vector3d perp = mW.direction.cross(fW.direction);
    fW.point = mW.point + rng.uniform(-1, 1) * mW.direction + v * perp.normalized() +
               rng.uniform(-1, 1) * fW.direction;
  } else if (t == "tangent") {
    if (kind.fixed == K::kCylinder && kind.mobile == K::kCylinder) {
      fW.direction = (rng.integer(0, 1) ? 1.0 : -1.0) * mW.direction;
      fW.point = mW.point + (fW.radius + mW.radius) * rng.perpendicular(mW.direction);
    } else {
      const bool plane_fixed = kind.fixed == K::kPlane;
      const Feature& C = plane_fixed ? mW : fW;
      const double s = kind.orientation == Orientation::kOpposed ? 1.0 : -1.0;  // signed axis dist
      if (plane_fixed) {
        fW.direction = rng.perpendicular(mW.direction);
        const Vector3d n = fW.direction;
        // axis point a: (a − plane point)·n = s r  =>  plane point = a − s r n (+ in-plane).
        fW.point = C.point - s * C.radius * n + (in_plane_jitter - in_plane_jitter.dot(n) * n);
      } else {
        // Fixed cylinder, mobile plane (normal n_W): plane point q with (a − q)·n = s r.
        const Vector3d n = mW.direction;
        fW.direction = rng.perpendicular(n);
        fW.point = mW.point + s * fW.radius * n + (in_plane_jitter - in_plane_jitter.dot(n) * n);
      }
    }
  }
  c.value = c.min = c.max = v;
  if (t == "skew-distance") {
    c.type = "distance";
    c.parallel = false;
  }
  if (t == "tangent" && (kind.fixed == K::kLine || kind.mobile == K::kLine))
    c.value = c.min = c.max = 0.0;
  c.fixed = fW.placed(X_WF.inverse());
  if (kp.noise > 0) {
    // Rounding-level noise on the fixed feature (as data exported with finite precision), so the
    // special cases sit within the tolerance instead of exactly on it.
    c.fixed.point += kp.noise * rng.point(1.0);
    c.fixed.direction = (c.fixed.direction + kp.noise * rng.point(1.0)).normalized();
  }
  c.mobile = m;
  c.fixed_name = "f" + tag;
  c.mobile_name = reusing ? reuse->name : "m" + tag;
  pb.fixed.features.push_back({c.fixed_name, c.fixed});
  if (!reusing) pb.mobile.features.push_back({c.mobile_name, c.mobile});
  pb.constraints.push_back(c);
}

}  // namespace relpos::test
