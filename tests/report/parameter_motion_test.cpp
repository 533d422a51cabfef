// Each parameter's motion (docs/spec.md §2.5, issue 17), checked against the branch's own poses:
// turning the nearest pose about the reported axis and point (or sliding it along the reported
// direction) by the parameter's change times its rate is, to first order, the pose the branch
// gives at the changed parameter.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

namespace fs = std::filesystem;

// The nearest pose moved as the motion says, by a change d of the parameter.
Isometry3d moved(const Isometry3d& X, const ParameterMotion& m, double d) {
  Isometry3d step = Isometry3d::Identity();
  if (m.type == ParameterMotion::Type::kTranslation) {
    step.translation() = m.axis * (m.rate * d);
  } else {
    const double turn = m.rate * d;
    step.linear() = Eigen::AngleAxisd(turn, m.axis).toRotationMatrix();
    step.translation() = m.point - step.linear() * m.point + m.axis * (m.pitch * turn);
  }
  return step * X;
}

double gap(const Isometry3d& a, const Isometry3d& b) {
  return (a.translation() - b.translation()).norm() + rotationDistance(a.linear(), b.linear());
}

// First order: the gap between the branch's pose and the moved one shrinks as d² (by about 4
// when d halves), or is rounding already.
void expectFirstOrder(const Manifold& m, const Params& at, int i, const ParameterMotion& mo,
                      const std::string& where) {
  const Parameter p = m.parameter(i);
  const double room = p.periodic ? 1.0 : std::min(p.max - at[i], 1.0);
  const double sign = room > 1e-3 ? 1.0 : -1.0;  // at the upper bound: step down
  const double d = sign * 1e-3;
  const Isometry3d X = m.pose(at);
  auto error = [&](double step) {
    Params t = at;
    t[i] += step;
    return gap(m.pose(t), moved(X, mo, step));
  };
  const double e1 = error(d), e2 = error(d / 2);
  const double moved_by = std::abs(d) * mo.rate;
  // against the motion itself (1e-3 of a rate): a wrong axis or point is off by about that
  EXPECT_TRUE(e1 < 1e-9 * (1 + moved_by) || (e1 < 1e-2 * moved_by && e2 < 0.35 * e1))
      << where << " parameter " << p.name << ": gap " << e1 << " at d, " << e2 << " at d/2";
}

TEST(ParameterMotion, EveryParameterMovesThePoseAsItsMotionSays) {
  int checked = 0;
  for (const char* folder : {"examples", "scenarios", "rules"})
    for (const auto& e : fs::directory_iterator(std::string(RELPOS_DATA_DIR) + "/" + folder)) {
      if (e.path().extension() != ".json") continue;
      ParseResult r = parseSpecFile(e.path().string(), builtinRegistry());
      if (!r.problem) continue;
      const Solution s = solve(*r.problem, builtinRegistry());
      const Report rep = evaluate(*r.problem, s, ReportOptions());
      ASSERT_EQ(rep.branches.size(), s.branches.size());
      for (std::size_t b = 0; b < s.branches.size(); ++b) {
        const Manifold& m = *s.branches[b].manifold;
        for (int i = 0; i < m.dof(); ++i) {
          const ParameterMotion& mo = rep.branches[b].motions[static_cast<std::size_t>(i)];
          const std::string where = e.path().filename().string() + " branch " + std::to_string(b);
          if (mo.type == ParameterMotion::Type::kNone) continue;
          EXPECT_NE(mo.type, ParameterMotion::Type::kUnknown) << where;
          EXPECT_NEAR(mo.axis.norm(), 1.0, 1e-12) << where;
          EXPECT_GT(mo.rate, 0.0) << where;
          expectFirstOrder(m, rep.branches[b].nearest.parameters, i, mo, where);
          ++checked;
        }
      }
    }
  EXPECT_GT(checked, 300);
}

TEST(ParameterMotion, RangeParametersNameTheirConstraint) {
  const std::string file = std::string(RELPOS_DATA_DIR) + "/scenarios/scenario-b-seam-welding.json";
  ParseResult r = parseSpecFile(file, builtinRegistry());
  ASSERT_TRUE(r.problem);
  const Report rep = evaluate(*r.problem, solve(*r.problem, builtinRegistry()), ReportOptions());
  ASSERT_FALSE(rep.branches.empty());
  for (const BranchReport& br : rep.branches)
    for (int i = 0; i < br.dof; ++i) {
      const std::string name = br.parameters[static_cast<std::size_t>(i)].name;
      const ParameterMotion& mo = br.motions[static_cast<std::size_t>(i)];
      // The spec: constraint 1 is the tip's distance range along the seam, 2 the torch's angle
      // range; the turns (phi, theta) span no range.
      if (name == "distance") {
        EXPECT_EQ(mo.constraint, 1);
        EXPECT_EQ(mo.constraint_id, "between start and end");
        EXPECT_EQ(mo.type, ParameterMotion::Type::kTranslation);
        EXPECT_NEAR(std::abs(mo.axis.dot(Vector3d::UnitX())), 1.0, 1e-9);  // along the seam
      } else if (name == "alpha") {
        EXPECT_EQ(mo.constraint, 2);
        EXPECT_EQ(mo.type, ParameterMotion::Type::kRotation);
      } else {
        EXPECT_EQ(mo.constraint, -1) << name;
      }
    }
}

TEST(ParameterMotion, AFreeSpinTurnsAboutTheFixedAxis) {
  // A peg coaxial with a hole (x = 1, y = 2, along z): its spin's axis is the hole's line.
  Problem p;
  p.addFixedFeature("hole", Feature::makeLine({1, 2, 0}, {0, 0, 1}))
      .addMobileFeature("peg", Feature::makeLine({0, 0, 0}, {0, 0, 1}));
  p.addConstraint("coincident", "hole", "peg");
  p.mobile.pose.translation() = Vector3d(4, 0, 7);
  const Report rep = evaluate(p, solve(p, builtinRegistry()), ReportOptions());
  ASSERT_EQ(rep.branches.size(), 1u);
  bool spin = false, slide = false;
  for (int i = 0; i < rep.branches[0].dof; ++i) {
    const ParameterMotion& mo = rep.branches[0].motions[static_cast<std::size_t>(i)];
    if (mo.type == ParameterMotion::Type::kRotation) {
      spin = true;
      EXPECT_NEAR(std::abs(mo.axis.z()), 1.0, 1e-9);
      EXPECT_NEAR(mo.point.x(), 1.0, 1e-9);
      EXPECT_NEAR(mo.point.y(), 2.0, 1e-9);
    } else if (mo.type == ParameterMotion::Type::kTranslation) {
      slide = true;
      EXPECT_NEAR(std::abs(mo.axis.z()), 1.0, 1e-9);
    }
  }
  EXPECT_TRUE(spin && slide);
}

}  // namespace
}  // namespace relpos::test
