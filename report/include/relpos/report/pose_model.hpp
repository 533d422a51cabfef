#pragma once
// A branch's pose function in a form another program can evaluate without relpos: a product of
// screws, one per parameter, when the branch is one (most closed forms are), else a table of its
// poses on a grid of its parameters. The TSR export (tsr.hpp) and the viewer (relpos view,
// docs/spec.md §3.12) write branches this way.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

// One factor of a product: a turn about the line (point, axis), advancing pitch per radian along
// it (a screw; 0 for a plain turn), or a slide along axis; `rate` radians or lengths per unit of
// parameter `param`. A rigid factor moves the whole object; a separable branch's (its orientation
// and position set by different parameters, docs/spec.md §2) turns only the orientation
// (`orients`) or carries only the position (`moves`).
struct ScrewFactor {
  int param = 0;
  bool turn = false;
  bool orients = true, moves = true;
  Vector3d axis{0, 0, 1}, point{0, 0, 0};
  double pitch = 0.0;
  double rate = 1.0;
  double lo = 0.0, hi = 0.0;  // the range of rate·(θ_param − θ*_param) over the parameter's box
};

// The rigid motion of factor f advanced by x = rate·(θ_param − θ*_param).
Isometry3d exponential(const ScrewFactor& f, double x);

// The branch's parameters as a product X(θ) = Π_k exp(ξ_k (θ_k − θ*_k)) · X(θ*) about θ* = `at`,
// the order found among every order of the factors and checked on the branch itself at the
// corners of its box and at random points of it, to 1e-9 of the problem's size and 1e-9 rad (so a
// plugin's branch qualifies as a built-in one does). Unbounded lengths are boxed to ± window
// about θ* (*windowed then). `screws`: whether a turn that advances counts as a factor (a TSR has
// no such bound). Empty with the reason in *why when the branch is no such product.
std::optional<std::vector<ScrewFactor>> screwProduct(const Problem& problem, const Branch& branch,
                                                     const Params& at, double window, bool screws,
                                                     std::string* why, bool* windowed);

// The branch as rigid turns and slides only (a TSR chain's factors, in order, with their bounds
// lo/hi): screwProduct without screws, or a separable product rewritten as one where it can be —
// its position sliding, or first turning about an axis its orientation turns freely about (a
// grasp around a can: the turn then carries the whole object, and the orientation's remaining
// turn about that axis is a full one). Checked on the branch like screwProduct.
std::optional<std::vector<ScrewFactor>> rigidProduct(const Problem& problem, const Branch& branch,
                                                     const Params& at, double window,
                                                     std::string* why, bool* windowed);

// A branch's poses for a picture: the screw product when there is one, or the separable one (the
// orientation a product of turns of R(θ*), the position a product of rigid motions of t(θ*)),
// checked likewise; else the poses on a grid
// of parameter values through θ* (`table_poses` of them at most), the pose of a parameter vector
// then that of the node nearest it.
struct PoseModel {
  Params at{};  // θ*: the nearest pose's parameters
  Isometry3d X_at = Isometry3d::Identity();
  // Each parameter's range: its bounds, an unbounded length ± window about θ*. For a table, the
  // grid's first and last values.
  std::array<std::array<double, 2>, kMaxDof> range{};
  bool product = false;
  std::vector<ScrewFactor> factors;  // product: in order, leftmost first
  // The point of the object (in its frame) the moving factors carry: the origin for a rigid
  // product; a separable one's where its turns' axes meet. X(θ) = [R, P·(X(θ*)·pivot) − R·pivot].
  Vector3d pivot = Vector3d::Zero();
  // A table: count[i] values of parameter i from range[i][0] in steps step[i]; the poses in
  // row-major order (the last parameter fastest), `valid` false where the branch's code threw.
  std::array<int, kMaxDof> count{};
  std::array<double, kMaxDof> step{};
  std::vector<Isometry3d> table;
  std::vector<bool> valid;
};

PoseModel poseModelOf(const Problem& problem, const Branch& branch, const Params& at, double window,
                      int table_poses = 4096);

// The model's pose at θ (a table's node nearest θ); nullopt for a node where the branch threw.
std::optional<Isometry3d> modelPose(const PoseModel& model, int dof, const Params& theta);

}  // namespace relpos
