#include "known_problems.hpp"

#include <cmath>
#include <string>

namespace relpos::complete::test {
namespace {

std::string name(const char* base, int i) { return base + std::to_string(i); }

double pointLineDistance(const Vector3d& p, const Vector3d& a, const Vector3d& u) {
  return (p - a).cross(u.normalized()).norm();
}

}  // namespace

Vector3d randomVector(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double x = u(rng), y = u(rng);
  return {x, y, u(rng)};
}

Isometry3d randomPose(std::mt19937_64& rng) {
  const Vector3d axis = randomVector(rng).normalized();
  Isometry3d X = Isometry3d::Identity();
  X.linear() = axisAngle(axis, 3.0 * randomVector(rng).x());
  X.translation() = randomVector(rng);
  return X;
}

Problem sixSix(std::mt19937_64& rng, const Isometry3d& X) {
  Problem p;
  p.name = "six-six";
  for (int i = 0; i < 6; ++i) {
    const Vector3d a = 2.0 * randomVector(rng), b = randomVector(rng);
    p.addFixedFeature(name("A", i), Feature::makePoint(a));
    p.addMobileFeature(name("B", i), Feature::makePoint(b));
    p.addConstraint("distance", name("A", i), name("B", i), (X * b - a).norm());
  }
  return p;
}

Problem octahedral(std::mt19937_64& rng, const Isometry3d& X) {
  Problem p;
  p.name = "octahedral";
  Vector3d a[3], b[3];
  for (int i = 0; i < 3; ++i) {
    a[i] = 2.0 * randomVector(rng), b[i] = randomVector(rng);
    p.addFixedFeature(name("A", i), Feature::makePoint(a[i]));
    p.addMobileFeature(name("B", i), Feature::makePoint(b[i]));
  }
  for (int i = 0; i < 3; ++i)
    for (int j : {i, (i + 1) % 3})
      p.addConstraint("distance", name("A", i), name("B", j), (X * b[j] - a[i]).norm());
  return p;
}

Problem mixed(int k, std::mt19937_64& rng, const Isometry3d& X) {
  Problem p;
  p.name = "mixed" + std::to_string(k);
  const Matrix3d& R = X.linear();
  auto fixedPoint = [&](const char* n) {
    const Vector3d a = randomVector(rng);
    p.addFixedFeature(n, Feature::makePoint(a));
    return a;
  };
  auto mobilePoint = [&](const char* n) {
    const Vector3d b = randomVector(rng);
    p.addMobileFeature(n, Feature::makePoint(b));
    return b;
  };
  auto fixedDir = [&](const char* n, bool plane) {
    const Vector3d a = randomVector(rng), u = randomVector(rng).normalized();
    p.addFixedFeature(n, plane ? Feature::makePlane(a, u) : Feature::makeLine(a, u));
    return Feature::makeLine(a, u);
  };
  auto mobileDir = [&](const char* n, bool plane) {
    const Vector3d b = randomVector(rng), m = randomVector(rng).normalized();
    p.addMobileFeature(n, plane ? Feature::makePlane(b, m) : Feature::makeLine(b, m));
    return Feature::makeLine(b, m);
  };
  switch (k) {
    case 0: {  // a point on a point (3), a distance, a plane's signed distance, an angle
      const Vector3d b = mobilePoint("b");
      p.addFixedFeature("A", Feature::makePoint(X * b));
      p.addConstraint("coincident", "A", "b");
      const Vector3d a1 = fixedPoint("A1"), b1 = mobilePoint("b1");
      p.addConstraint("distance", "A1", "b1", (X * b1 - a1).norm());
      const Feature pl = fixedDir("P", true);
      const Vector3d b2 = mobilePoint("b2");
      p.addConstraint("distance", "P", "b2", (X * b2 - pl.point).dot(pl.direction));
      const Feature l = fixedDir("L", false), m = mobileDir("m", false);
      p.addConstraint("angle", "L", "m", std::acos(l.direction.dot(R * m.direction)));
      break;
    }
    case 1: {  // points on lines both ways (2 + 2), point-line distances both ways
      const Vector3d b = mobilePoint("b");
      const Vector3d u = randomVector(rng).normalized();
      p.addFixedFeature("L", Feature::makeLine(X * b - 0.4 * u, u));  // through X b
      p.addConstraint("coincident", "L", "b");
      const Vector3d a = fixedPoint("A");
      const Vector3d m = randomVector(rng).normalized();
      p.addMobileFeature("m", Feature::makeLine(X.inverse() * a + 0.7 * m, m));
      p.addConstraint("coincident", "A", "m");
      const Feature l2 = fixedDir("L2", false);
      const Vector3d b2 = mobilePoint("b2");
      p.addConstraint("distance", "L2", "b2", pointLineDistance(X * b2, l2.point, l2.direction));
      const Vector3d a3 = fixedPoint("A3");
      const Feature m3 = mobileDir("m3", false);
      p.addConstraint("distance", "A3", "m3",
                      pointLineDistance(a3, X * m3.point, R * m3.direction));
      break;
    }
    case 2: {  // a parallelism (2), signed distances both ways, a line-plane angle, a distance
      const Vector3d m = randomVector(rng).normalized();
      p.addMobileFeature("m", Feature::makeLine(randomVector(rng), m));
      p.addFixedFeature("L", Feature::makeLine(randomVector(rng), R * m));
      p.addConstraint("parallel", "L", "m");
      const Feature pl = fixedDir("P", true);
      const Vector3d b = mobilePoint("b");
      p.addConstraint("distance", "P", "b", (X * b - pl.point).dot(pl.direction));
      const Vector3d a = fixedPoint("A");
      const Feature mp = mobileDir("Q", true);
      p.addConstraint("distance", "A", "Q", (a - X * mp.point).dot(R * mp.direction));
      const Feature l = fixedDir("L2", false);
      const Feature q2 = mobileDir("Q2", true);
      p.addConstraint("angle", "L2", "Q2", std::asin(l.direction.dot(R * q2.direction)));
      const Vector3d a4 = fixedPoint("A4"), b4 = mobilePoint("b4");
      p.addConstraint("distance", "A4", "b4", (X * b4 - a4).norm());
      break;
    }
    case 3: {  // coplanar planes, opposed (3), a point on a fixed line (2), a distance
      const Feature q = mobileDir("Q", true);
      p.addFixedFeature(
          "P", Feature::makePlane(X * q.point + 0.2 * (R * q.direction).cross(randomVector(rng)),
                                  -(R * q.direction)));
      p.addConstraint("coincident", "P", "Q", 0.0, Orientation::kOpposed);
      const Vector3d b = mobilePoint("b");
      const Vector3d u = randomVector(rng).normalized();
      p.addFixedFeature("L", Feature::makeLine(X * b + 0.5 * u, u));
      p.addConstraint("coincident", "L", "b");
      const Vector3d a = fixedPoint("A"), b2 = mobilePoint("b2");
      p.addConstraint("distance", "A", "b2", (X * b2 - a).norm());
      break;
    }
    case 5: {  // 'either' that changes the equations: a plane-plane distance (true: opposed)
      // and a cylinder-plane tangency (true: aligned), two subproblems each; a distance
      const Feature q = mobileDir("Q", true);
      const Vector3d nf = -(R * q.direction);
      p.addFixedFeature("P", Feature::makePlane(X * q.point - 0.3 * nf, nf));
      p.addConstraint("distance", "P", "Q", 0.3, Orientation::kEither);
      const Feature axis = mobileDir("Caxis", false);
      p.addMobileFeature("C", Feature::makeCylinder(axis.point, axis.direction, 0.25));
      const Vector3d n2 = (R * axis.direction).cross(randomVector(rng)).normalized();
      // The axis 0.25 behind the plane (its normal points away from the axis): aligned.
      p.addFixedFeature("P2", Feature::makePlane(X * axis.point + 0.25 * n2, n2));
      p.addConstraint("tangent", "P2", "C", 0.0, Orientation::kEither);
      const Vector3d a = fixedPoint("A"), b = mobilePoint("b");
      p.addConstraint("distance", "A", "b", (X * b - a).norm());
      break;
    }
    default: {  // a line-line distance (parallel, 3), a point on a cylinder, a line in a plane (2)
      const Feature m = mobileDir("m", false);
      const Vector3d off = (R * m.direction).cross(randomVector(rng)).normalized();
      p.addFixedFeature("L", Feature::makeLine(X * m.point + 0.6 * off, R * m.direction));
      p.addConstraint("distance", "L", "m", 0.6);
      const Vector3d b = mobilePoint("b");
      const Feature c = fixedDir("Caxis", false);
      p.addFixedFeature("C", Feature::makeCylinder(c.point, c.direction,
                                                   pointLineDistance(X * b, c.point, c.direction)));
      p.addConstraint("coincident", "C", "b");
      const Feature l = mobileDir("l", false);
      const Vector3d n = (R * l.direction).cross(randomVector(rng)).normalized();
      p.addFixedFeature("P", Feature::makePlane(X * l.point, n));
      p.addConstraint("coincident", "P", "l");
      break;
    }
  }
  return p;
}

Problem fourSpheres(std::mt19937_64& rng, const Vector3d& q, const Vector3d& w) {
  Problem p;
  p.name = "four-spheres";
  p.addMobileFeature("axis", Feature::makeLine(Vector3d::Zero(), Vector3d::UnitZ()));
  for (int i = 0; i < 4; ++i) {
    const Vector3d a = 2.0 * randomVector(rng);
    p.addFixedFeature(name("S", i), Feature::makePoint(a));
    p.addConstraint("distance", name("S", i), "axis", pointLineDistance(a, q, w));
  }
  return p;
}

void addRandomConstraint(Problem& p, std::mt19937_64& rng, const Isometry3d& X, int i) {
  const std::string F = "F" + std::to_string(i), M = "M" + std::to_string(i);
  const Matrix3d& R = X.linear();
  std::uniform_int_distribution<int> kind(0, 9);
  const Vector3d a = randomVector(rng), b = randomVector(rng), u = randomVector(rng).normalized(),
                 m = randomVector(rng).normalized();
  switch (kind(rng)) {
    case 0:
      p.addFixedFeature(F, Feature::makePoint(a));
      p.addMobileFeature(M, Feature::makePoint(b));
      p.addConstraint("distance", F, M, (X * b - a).norm());
      break;
    case 1:
      p.addFixedFeature(F, Feature::makeLine(a, u));
      p.addMobileFeature(M, Feature::makePoint(b));
      p.addConstraint("distance", F, M, (X * b - a).cross(u).norm());
      break;
    case 2:
      p.addFixedFeature(F, Feature::makePoint(a));
      p.addMobileFeature(M, Feature::makeLine(b, m));
      p.addConstraint("distance", F, M, (a - X * b).cross(R * m).norm());
      break;
    case 3:
      p.addFixedFeature(F, Feature::makePlane(a, u));
      p.addMobileFeature(M, Feature::makePoint(b));
      p.addConstraint("distance", F, M, (X * b - a).dot(u));
      break;
    case 4:
      p.addFixedFeature(F, Feature::makePoint(a));
      p.addMobileFeature(M, Feature::makePlane(b, m));
      p.addConstraint("distance", F, M, (a - X * b).dot(R * m));
      break;
    case 5:
      p.addFixedFeature(F, Feature::makeLine(a, u));
      p.addMobileFeature(M, Feature::makeLine(b, m));
      p.addConstraint("angle", F, M, std::acos(u.dot(R * m)));
      break;
    case 6:
      p.addFixedFeature(F, Feature::makePlane(a, u));
      p.addMobileFeature(M, Feature::makeLine(b, m));
      p.addConstraint("angle", F, M, std::asin(u.dot(R * m)));
      break;
    case 7:
      p.addFixedFeature(F, Feature::makeLine(X * b + 0.5 * u, u));
      p.addMobileFeature(M, Feature::makePoint(b));
      p.addConstraint("coincident", F, M);
      break;
    case 8:
      p.addFixedFeature(F, Feature::makePlane(X * b + u.cross(randomVector(rng)), u));
      p.addMobileFeature(M, Feature::makePoint(b));
      p.addConstraint("coincident", F, M);
      break;
    default:
      p.addFixedFeature(F, Feature::makeLine(a, R * m));
      p.addMobileFeature(M, Feature::makeLine(b, m));
      p.addConstraint("parallel", F, M);
      break;
  }
}
Problem scaledAndMoved(const Problem& p, double s, const Vector3d& d_W, const Vector3d& d_M) {
  Problem out = p;
  // Fixed features are given in the fixed frame: move them so that, placed, they move by d_W.
  const Vector3d d_F = p.fixed.pose.linear().transpose() * d_W;
  out.fixed.pose.translation() *= s;
  auto moveFixed = [&](Feature& f) {
    f.point = s * f.point + d_F;
    f.radius *= s;
  };
  auto moveMobile = [&](Feature& f) {
    f.point = s * f.point + d_M;
    f.radius *= s;
  };
  for (NamedFeature& f : out.fixed.features) moveFixed(f.feature);
  for (NamedFeature& f : out.mobile.features) moveMobile(f.feature);
  for (InputConstraint& c : out.constraints) {
    moveFixed(c.fixed);
    moveMobile(c.mobile);
    if (c.type == "distance") c.value *= s, c.min *= s, c.max *= s;
  }
  return out;
}

Isometry3d movedPose(const Isometry3d& X, double s, const Vector3d& d_W, const Vector3d& d_M) {
  Isometry3d Y = X;
  Y.translation() = s * X.translation() + d_W - X.linear() * d_M;
  return Y;
}

}  // namespace relpos::complete::test
