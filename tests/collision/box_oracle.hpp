#pragma once
// An exact collision oracle for boxes and spheres, written in the test (not FCL): the
// separating-axis test for two oriented boxes, whose smallest overlap over the 15 candidate axes
// is the penetration depth of two convex polyhedra; the closest point of a box to a sphere's
// centre for a sphere.
#include <algorithm>
#include <cmath>
#include <limits>

#include "relpos/core/geometry.hpp"

namespace relpos::test {

struct Box {
  Isometry3d X;  // centre and axes in the world
  Vector3d h;    // half-extents
};

// Penetration depth (> 0 overlapping, <= 0 separated or touching; when separated, minus a lower
// bound of the gap).
inline double boxPenetration(const Box& a, const Box& b) {
  Vector3d axes[15];
  int n = 0;
  for (int i = 0; i < 3; ++i) axes[n++] = a.X.linear().col(i);
  for (int i = 0; i < 3; ++i) axes[n++] = b.X.linear().col(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vector3d c = a.X.linear().col(i).cross(b.X.linear().col(j));
      if (c.norm() > 1e-9) axes[n++] = c.normalized();
    }
  const Vector3d d = b.X.translation() - a.X.translation();
  double depth = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    const Vector3d& u = axes[k];
    double ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) {
      ra += a.h[i] * std::abs(a.X.linear().col(i).dot(u));
      rb += b.h[i] * std::abs(b.X.linear().col(i).dot(u));
    }
    depth = std::min(depth, ra + rb - std::abs(d.dot(u)));
  }
  return depth;
}

// Signed distance from a sphere (centre c, radius r) to a box: > 0 apart, < 0 overlapping by
// up to that much (exact when the centre is outside the box).
inline double sphereBoxDistance(const Vector3d& c, double r, const Box& b) {
  const Vector3d p = b.X.inverse() * c;
  const Vector3d q = p.cwiseMax(-b.h).cwiseMin(b.h);
  if ((p - q).norm() > 0) return (p - q).norm() - r;
  const Vector3d inside = b.h - p.cwiseAbs();
  return -inside.minCoeff() - r;
}

}  // namespace relpos::test
