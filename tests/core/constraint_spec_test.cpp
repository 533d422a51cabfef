// Problem::addConstraint(ConstraintSpec): everything a spec's constraint may say, in code
// (issue 17), read as the spec reader reads the same JSON and solved alike.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"

namespace relpos {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A torch over a seam: the fixed seam line and floor plane, the mobile tip and axis.
Problem weldInCode() {
  Problem p;
  p.addFixedFeature("seam", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addFixedFeature("floor", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("pipe", Feature::makeCylinder({0, 1, 0}, {1, 0, 0}, 0.2))
      .addMobileFeature("tip", Feature::makePoint({0, 0, 0.3}))
      .addMobileFeature("axis", Feature::makeLine({0, 0, 0}, {0, 0, 1}));
  p.addConstraint(ConstraintSpec("coincident", "seam", "tip").id("on the seam"))
      .addConstraint(ConstraintSpec("angle", "floor", "axis")
                         .range(0.6, 0.95)
                         .orientation(Orientation::kEither)
                         .id("work angle"));
  return p;
}

constexpr const char* kWeldSpec = R"({
  "fixed": {"name": "fixed", "features": {
    "seam": {"line": {"point": [0, 0, 0], "direction": [1, 0, 0]}},
    "floor": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
    "pipe": {"cylinder": {"point": [0, 1, 0], "direction": [1, 0, 0], "radius": 0.2}}}},
  "mobile": {"name": "mobile", "features": {
    "tip": {"point": [0, 0, 0.3]},
    "axis": {"line": {"point": [0, 0, 0], "direction": [0, 0, 1]}}}},
  "constraints": [
    {"type": "coincident", "fixed": "seam", "mobile": "tip", "id": "on the seam"},
    {"type": "angle", "fixed": "floor", "mobile": "axis", "min": 0.6, "max": 0.95,
     "orientation": "either", "id": "work angle"}]})";

void expectSameConstraint(const InputConstraint& a, const InputConstraint& b) {
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.fixed_name, b.fixed_name);
  EXPECT_EQ(a.mobile_name, b.mobile_name);
  EXPECT_EQ(a.has_value, b.has_value);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
  EXPECT_EQ(a.orientation, b.orientation);
  EXPECT_EQ(a.parallel, b.parallel);
}

TEST(ConstraintSpec, ARangeInCodeIsTheRangeOfTheSpec) {
  const ParseResult r = parseSpec(kWeldSpec, builtinRegistry());
  ASSERT_TRUE(r.problem);
  const Problem code = weldInCode();
  ASSERT_EQ(code.constraints.size(), r.problem->constraints.size());
  for (std::size_t i = 0; i < code.constraints.size(); ++i)
    expectSameConstraint(code.constraints[i], r.problem->constraints[i]);

  const Solution a = solve(code, builtinRegistry()), b = solve(*r.problem, builtinRegistry());
  ASSERT_EQ(a.status, Status::kSolved) << a.message;
  EXPECT_EQ(test::describeBranches(a), test::describeBranches(b));
  // Every pose of every branch within the range: the evaluator written from the spec.
  EXPECT_LE(test::worstSampledViolation(code, a, 200, 7), 1e-9);
  // The range is there: an angle outside it is not a pose of the answer.
  bool bounded = false;
  for (const Branch& br : a.branches)
    for (int i = 0; i < br.manifold->dof(); ++i) {
      const Parameter q = br.manifold->parameter(i);
      bounded = bounded || (std::isfinite(q.min) && std::isfinite(q.max) && !q.periodic);
    }
  EXPECT_TRUE(bounded) << test::describeBranches(a);
}

TEST(ConstraintSpec, OneSidedRangesAreOpenOnTheOtherSide) {
  Problem p = weldInCode();
  p.addConstraint(ConstraintSpec("distance", "floor", "tip").atMost(0.5))
      .addConstraint(ConstraintSpec("distance", "floor", "tip").atLeast(-0.5));
  const InputConstraint &most = p.constraints[2], &least = p.constraints[3];
  EXPECT_FALSE(most.has_value);
  EXPECT_EQ(most.min, -kInf);
  EXPECT_EQ(most.max, 0.5);
  EXPECT_FALSE(least.has_value);
  EXPECT_EQ(least.min, -0.5);
  EXPECT_EQ(least.max, kInf);
  // Both, chained in either order: both bounds.
  p.addConstraint(ConstraintSpec("distance", "floor", "tip").atLeast(-0.5).atMost(0.5))
      .addConstraint(ConstraintSpec("distance", "floor", "tip").atMost(0.5).atLeast(-0.5));
  for (std::size_t k : {4u, 5u}) {
    EXPECT_EQ(p.constraints[k].min, -0.5);
    EXPECT_EQ(p.constraints[k].max, 0.5);
  }
}

TEST(ConstraintSpec, ExactValuesSkewLinesAndCylinderAxes) {
  Problem p = weldInCode();
  p.addConstraint(ConstraintSpec("distance", "pipe.axis", "axis").value(0.4).parallel(false));
  const InputConstraint& c = p.constraints.back();
  EXPECT_TRUE(c.has_value);
  EXPECT_EQ(c.value, 0.4);
  EXPECT_EQ(c.min, 0.4);
  EXPECT_EQ(c.max, 0.4);
  EXPECT_FALSE(c.parallel);
  EXPECT_EQ(c.fixed.kind, FeatureKind::kLine);  // the cylinder's axis
  // A range whose ends meet is the exact value, as in a spec.
  p.addConstraint(ConstraintSpec("distance", "floor", "tip").range(0.25, 0.25));
  EXPECT_TRUE(p.constraints.back().has_value);
  EXPECT_EQ(p.constraints.back().value, 0.25);
  // The old form still gives an exact value.
  p.addConstraint("distance", "floor", "tip", 0.3);
  EXPECT_TRUE(p.constraints.back().has_value);
  EXPECT_EQ(p.constraints.back().max, 0.3);
}

TEST(ConstraintSpec, WhatASpecWouldRefuseIsAnInvalidArgument) {
  Problem p = weldInCode();
  const std::size_t before = p.constraints.size();
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip").value(1).atMost(2)),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip").range(2, 1)),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip").value(std::nan(""))),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip").atLeast(std::nan(""))),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip").value(kInf)),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "floor", "tip2").value(1)),
               std::invalid_argument);
  EXPECT_THROW(p.addConstraint(ConstraintSpec("distance", "seam.axis", "tip").value(1)),
               std::invalid_argument);  // a line has no axis
  try {
    p.addConstraint(ConstraintSpec("distance", "floor", "tip").range(2, 1).id("height"));
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'height'"), std::string::npos) << e.what();
  }
  EXPECT_EQ(p.constraints.size(), before);  // nothing added by a refused one
}

}  // namespace
}  // namespace relpos
