#pragma once
// What the pose and line encoders share (pose_encoding.cpp, line_encoding.cpp): the frames the
// problem is normalised to, the parameter slots (a feature's coordinates shared by every
// equation on it), and the constraints' features placed and normalised.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "relpos/complete/study.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos::complete::detail {

// The middle of each side's box of constrained support points, and the longest of the boxes'
// diagonals and the length values (1 when all are 0).
Normalisation normalisationOf(const Problem& problem);

// One constraint's features in the normalised frames: fixed ones placed in the world by the
// fixed pose, both moved and scaled; directions unchanged.
struct NormalisedConstraint {
  Feature fixed, mobile;
  double value = 0.0;  // a length scaled, an angle as given
};
NormalisedConstraint normalised(const Problem& problem, const InputConstraint& c,
                                const Normalisation& n);

// Parameter slots. Equal coordinates of one side and role (point or direction) share a slot:
// two legs on one point, a plane's normal in two equations. The sharing pattern is part of the
// family's signature (slots are numbered in order of first use).
class Slots {
 public:
  enum Side : char { kFixed = 'F', kMobile = 'M' };
  enum Role : char { kPoint = 'p', kDirection = 'd' };
  explicit Slots(std::vector<double>* params) : params_(params) {}
  int shared(Side side, Role role, const Vector3d& v);
  int unique(const Vector3d& v);
  int value(double v);
  int size() const { return static_cast<int>(params_->size()); }

 private:
  std::vector<double>* params_;
  std::map<std::tuple<char, char, double, double, double>, int> shared_;
};

// Two unit vectors completing unit u to an orthonormal basis (the normals of two planes meeting
// in a line along u).
void normalsAcross(const Vector3d& u, Vector3d* n1, Vector3d* n2);

// Whether angle v is `at` (0, π, ±π/2: where a cosine or sine is ±1, a parallelism rather than
// one equation, whose ±1 is a double root) to the rounding of a value converted from degrees
// (kAngleRangeSlack: 180° is an ulp or so beyond π).
bool angleAt(double v, double at);

// The constraints' indices in a canonical order (by type, kinds, orientation, value and the
// features' coordinates): the encoding of a permutation of the constraints is the same member of
// the same family, so its answer is the same.
std::vector<int> canonicalOrder(const Problem& problem);

// Whether the constraint type is a built-in one this stage encodes (with its exact value).
bool isEncodedType(const std::string& type);

}  // namespace relpos::complete::detail
