#pragma once
// Branches as Task Space Region chains (Berenson et al., as personalrobotics/tsr uses them;
// docs/spec.md §3.11, issue 17): the mobile object's pose is the product over the chain's links of
// T0_w · Xform(b) · Tw_e, b within Bw (rows x, y, z, roll, pitch, yaw; Xform(b) the translation
// (x, y, z) times Rz(yaw)·Ry(pitch)·Rx(roll)). Every link after the first has T0_w = identity:
// the libraries start each later link at the pose so far, whatever its T0_w.
//
// A branch has an exact chain when its poses are a product of exponentials: a turn about a fixed
// line or a slide along a fixed direction per parameter, applied in some order to one pose of it.
// That is found from the parameters' motions (relpos/io/report.hpp) and then checked on the
// branch itself, pose by pose, so a plugin's branch qualifies as well as a built-in one.
#include <array>
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"
#include "relpos/core/solution.hpp"

namespace relpos {

struct TsrLink {
  Isometry3d T0_w = Isometry3d::Identity();
  Isometry3d Tw_e = Isometry3d::Identity();
  std::array<std::array<double, 2>, 6> Bw{};  // x, y, z, roll, pitch, yaw: {min, max}
};

struct TsrExport {
  bool exact = false;          // a chain whose poses are exactly poses of the branch
  std::vector<TsrLink> chain;  // empty when !exact
  std::string why;             // !exact: why the branch has no chain
  // An unbounded length parameter is bounded in the chain to ± window about the nearest pose's
  // (TSRs are boxes): the chain is then the part of the branch within that window.
  bool windowed = false;
};

// The chain of `branch` about parameters `at` (the branch's nearest pose's); none for a numeric
// branch (a chart is no closed form). `window`: the half-width given to unbounded lengths (> 0).
TsrExport tsrChainOf(const Problem& problem, const Branch& branch, const Params& at,
                     double window);

// The pose of a chain at one b per link (the TSR product).
Isometry3d tsrChainPose(const std::vector<TsrLink>& chain,
                        const std::vector<std::array<double, 6>>& b);

}  // namespace relpos
