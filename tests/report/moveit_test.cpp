// Branches as MoveIt goal constraints (relpos/report/moveit.hpp, issue 17): inside means valid.
// Every pose the constraints admit — the constrained point anywhere in the box, the orientation
// anywhere within the tolerances (XYZ Euler angles, as MoveIt measures them) — satisfies the
// spec by the tests' evaluator; an exact goal admits its branch's nearest pose.
#include "relpos/report/moveit.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <random>
#include <string>

#include "evaluator.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

// A pose the goal admits: box coordinates u and Euler angles e, each in [-1, 1] of its range.
Isometry3d admitted(const MoveItGoal& g, const Vector3d& u, const Vector3d& e) {
  const Matrix3d R = g.orientation.toRotationMatrix() *
                     (Eigen::AngleAxisd(e.x() * g.axis_tolerances.x(), Vector3d::UnitX()) *
                      Eigen::AngleAxisd(e.y() * g.axis_tolerances.y(), Vector3d::UnitY()) *
                      Eigen::AngleAxisd(e.z() * g.axis_tolerances.z(), Vector3d::UnitZ()))
                         .toRotationMatrix();
  const Vector3d point = g.box_pose * (0.5 * g.box_dimensions.cwiseProduct(u));
  Isometry3d X = Isometry3d::Identity();
  X.linear() = R;
  X.translation() = point - R * g.target_point_offset;
  return X;
}

TEST(MoveItGoal, EveryAdmittedPoseSatisfiesTheSpec) {
  int exact = 0, goals = 0;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const char* folder : {"examples", "scenarios", "rules"})
    for (const auto& e : fs::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      if (!r.problem) continue;
      const Problem& p = *r.problem;
      const double size = std::max(1.0, p.lengthScale());
      for (const Branch& b : solve(p, builtinRegistry()).branches) {
        const NearestPose near = nearestOnBranch(b, p.mobile.pose);
        const MoveItGoal g = moveitGoalOf(p, b, near.parameters, 0.5);
        ++goals;
        exact += g.exact;
        EXPECT_TRUE(g.exact || !g.why.empty());
        for (int k = 0; k < 60; ++k) {
          const Vector3d box(u(rng), u(rng), u(rng)), euler(u(rng), u(rng), u(rng));
          int which = -1;
          const double v = worstViolation(p, admitted(g, box, euler), &which);
          EXPECT_LE(v, 1e-8 * size) << e.path().filename() << " (" << b.manifold->describe()
                                    << "): an admitted pose breaks constraint " << which;
        }
        if (g.exact) {  // the nearest pose is admitted: its point in the box, its turn within
          const Vector3d at = g.box_pose.inverse() * (near.pose * g.target_point_offset);
          for (int k = 0; k < 3; ++k)
            EXPECT_LE(std::abs(at[k]), 0.5 * g.box_dimensions[k] + 1e-9 * size);
        }
      }
    }
  EXPECT_GT(exact, goals / 4) << exact << " exact of " << goals;  // 52 of 170 at first
}

}  // namespace
}  // namespace relpos::test
