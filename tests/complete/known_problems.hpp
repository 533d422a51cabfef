#pragma once
// Problems built around a known answer, for the numeric stage's tests: random features, values
// read off a random true pose (or line) by docs/spec.md §1.9's definitions, so that the true pose
// is a solution whatever the encoding does.
#include <random>

#include "relpos/core/problem.hpp"

namespace relpos::complete::test {

Vector3d randomVector(std::mt19937_64& rng);  // each coordinate uniform in [-1, 1]
Isometry3d randomPose(std::mt19937_64& rng);

// 6 legs: distance between fixed point A_i and mobile point B_i (the general 6-6 platform).
Problem sixSix(std::mt19937_64& rng, const Isometry3d& X);
// 3 fixed and 3 mobile points, leg i from A_i to B_i and B_{i+1} (the octahedral manipulator).
Problem octahedral(std::mt19937_64& rng, const Isometry3d& X);
// The mixed problems: each gives 6 equations of other kinds (k = 0 … kMixedProblems − 1).
inline constexpr int kMixedProblems = 6;
Problem mixed(int k, std::mt19937_64& rng, const Isometry3d& X);

// Four fixed points and a mobile line (along z through the mobile origin), the distances of the
// points from the line (q, w) in the world: paper 001 §V-B's four spheres.
Problem fourSpheres(std::mt19937_64& rng, const Vector3d& q, const Vector3d& w);

// One random constraint between new features F<i> and M<i>, of a random kind (a distance of a
// point to a point, line or plane either way round, an angle, a point on a line or a plane, a
// parallelism), measured at X.
void addRandomConstraint(Problem& p, std::mt19937_64& rng, const Isometry3d& X, int i);

// The same problem with every length scaled by s, fixed features moved by d_W in the world and
// mobile ones by d_M in the mobile frame (the true pose X becomes movedPose(X, …)).
Problem scaledAndMoved(const Problem& p, double s, const Vector3d& d_W, const Vector3d& d_M);
Isometry3d movedPose(const Isometry3d& X, double s, const Vector3d& d_W, const Vector3d& d_M);

}  // namespace relpos::complete::test
