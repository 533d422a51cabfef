#pragma once
// A certified chart of a set of poses (docs/spec.md §8.7): about a base pose on the set where
// the m equations are independent, the six local coordinates y (pose_conditions.hpp) split into
// d = 6 − m tangent ones θ and m normal ones s (an orthonormal basis B: y = B·(θ, s)). Krawczyk's
// test, parametrised by θ over a box Θ, proves that for every θ in Θ exactly one s in the slice
// [−σ, σ]^m solves the equations — the set is, over Θ, the graph of s(θ): a d-dimensional
// piece of it, without singular point — and the interval enclosure of every inequality over
// Θ × slice proves that every pose of that piece meets them. pose(θ) is then that solution,
// found by Newton's method (the simplified step s ← s − Y·E contracts on the slice).
#include <array>
#include <vector>

#include "pose_conditions.hpp"

namespace relpos::complete::detail {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// At most six equations: their matrices have fixed capacity, so a chart's pose (Newton's method,
// run for every sample and nearest-pose query) allocates nothing.
using EquationVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
using EquationMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using EquationJacobian = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6>;

// The equations' residuals (g − target) at local coordinates y, and their Jacobian (rows:
// equations, columns: y) when J is set.
void equationsAt(const std::vector<Condition>& eqs, const Vector6d& y, EquationVector* e,
                 EquationJacobian* J = nullptr);

// A singular value under this fraction of the largest: the equations are dependent there (no
// chart; the dependent ones' reduction, dependent_equations.hpp, uses the same gap).
inline constexpr double kRankGap = 1e-7;

struct Chart {
  Matrix3d R0 = Matrix3d::Identity();  // the base pose, normalised (pose_conditions.hpp)
  Vector3d t0 = Vector3d::Zero();
  std::vector<Condition> equations, inequalities;  // in the base frame
  int m = 0, d = 6;
  Matrix6d basis = Matrix6d::Identity();  // columns: the d tangent, then the m normal directions
  Matrix6d Y = Matrix6d::Zero();          // the top-left m×m: (J·B_normal)⁻¹ at the base
  std::array<double, 6> radius{};         // Θ: θ_j in [−radius_j, radius_j]
  double slice = 0.0;                     // σ
};

// The chart at base pose (R0, t0) with its box not yet grown (radius 0): false when the base is
// not a regular point of the equations (more than six, or dependent: the smallest singular value
// of their Jacobian under 1e-7 of the largest) or an inequality does not hold there strictly.
bool makeChart(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0, Chart* out);

// Krawczyk's test and the inequalities' enclosure over the box `radius` (outward-rounded
// intervals): true with the slice σ when both hold.
bool certifyChart(const Chart& chart, const std::array<double, 6>& radius, double* slice);

// Grows the box from `start` (every tangent coordinate alike, then — `each_axis` — each alone)
// while certifyChart holds, up to `limit`; false when not even `start` holds.
bool growChart(Chart& chart, double start, double limit, bool each_axis = true);

// Whether every condition of `extra` (in the system's frame) holds within `tolerance` (per
// condition) at the exact pose of the chart's equations at θ = 0: Krawczyk's test proves that
// pose within a slice about the base as thin as the base's residual allows, and the conditions'
// enclosures over that slice are within their ranges so widened.
// `proven` (when set): per equation of `extra`, the bound on |g − value| so proven there.
bool holdAtExactBase(const Chart& chart, const std::vector<Condition>& extra,
                     const std::vector<double>& tolerance, std::vector<double>* proven = nullptr);

// The pose at θ (normalised): Newton's method on the slice.
void chartPose(const Chart& chart, const std::array<double, 6>& theta, Matrix3d* R, Vector3d* t);

// The local coordinates of pose (R, t) about the chart's base, and θ (the tangent part, within
// the box).
Vector6d localCoordinates(const Chart& chart, const Matrix3d& R, const Vector3d& t);
std::array<double, 6> chartProject(const Chart& chart, const Matrix3d& R, const Vector3d& t);

// The pose at local coordinates y about base (R0, t0).
void poseAt(const Matrix3d& R0, const Vector3d& t0, const Vector6d& y, Matrix3d* R, Vector3d* t);

}  // namespace relpos::complete::detail
