#pragma once
// A Problem as a member of a PoseFamily or a LineFamily (encoding.hpp): which equations each
// built-in constraint with an exact value becomes (docs/spec.md §1.9), the parameters of the real
// member, and what a real root must satisfy besides (the orientation of a parallelism). The
// geometry is centred and scaled first (study.hpp, Normalisation) so that the homotopy works
// with numbers of size 1 whatever the problem's units and placement.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "relpos/complete/encoding.hpp"
#include "relpos/complete/study.hpp"
#include "relpos/core/problem.hpp"
#include "relpos/core/tolerance.hpp"

namespace relpos::complete {

// A real root is a solution only if sign · (fixed · R mobile) > 0 (a parallelism's orientation:
// its two equations hold for both directions). For a line root R mobile is the line's w.
struct SignCheck {
  Vector3d fixed = Vector3d::UnitZ();   // world
  Vector3d mobile = Vector3d::UnitZ();  // mobile frame (line: the reference line's, ±)
  double sign = 1.0;
};

struct PoseEncoding {
  std::vector<PoseEquation> equations;
  std::vector<double> target;  // the real member's parameters
  Normalisation frames;
  Eigen::Vector4d chart = Eigen::Vector4d::Ones();
  std::vector<SignCheck> signs;
  // Constraints whose "either" orientation changes the equations (a plane-plane distance, a
  // cylinder-plane tangency) make 2^alternatives subproblems; this one is `alternative` (bit k:
  // the k-th such constraint opposed).
  int alternatives = 0;
  unsigned alternative = 0;
};

struct LineEncoding {
  std::vector<LineEquation> equations;
  std::vector<double> target;
  Normalisation frames;
  // The mobile line every mobile feature lies on (mobile frame, as given: not normalised).
  Vector3d mobile_point = Vector3d::Zero();
  Vector3d mobile_direction = Vector3d::UnitZ();
  std::vector<SignCheck> signs;
};

// Whether every mobile feature the constraints use lies on one line (lines and cylinders' axes,
// collinear within tol): the case encodeLine handles.
bool mobileFeaturesOnOneLine(const Problem& problem, const Tolerance& tol);

// The encodings. False, with the reason in *why, when a constraint is not one they encode (a
// range, a plugin's type, a skew line distance, a tangent to a line, …) or the equations are
// not as many as the unknowns (6 for a pose, 4 for a line). chart picks the chart c·e = 1 (0, 1:
// two fixed random real charts, the second for a retry).
bool encodePose(const Problem& problem, int chart, PoseEncoding* out, std::string* why,
                unsigned alternative = 0);
bool encodeLine(const Problem& problem, const Tolerance& tol, LineEncoding* out, std::string* why);

}  // namespace relpos::complete
