// Every translation shape (manifolds/src/translation/*.cpp) against its defining equations,
// evaluated here from the constraints themselves (not through shapeOf): for random rotations R
// and parameters t, the mobile point R p + T (or the fixed point against the mobile element moved
// by R, T) satisfies every constraint of the shape; projecting a point of the set gives back its
// parameters; and the separable manifold built on the shape contains exactly its own poses.
#include "relpos/manifolds/translation_part.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <ostream>
#include <string>

#include "constraint_measure.hpp"
#include "random_problems.hpp"
#include "relpos/manifolds/separable.hpp"

namespace relpos::test {
namespace {

namespace tr = manifolds::translation;
using manifolds::SeparableManifold;
using manifolds::TranslationPart;

Matrix3d randomRotation(Rng& rng) { return axisAngle(rng.unit(), rng.uniform(-kPi, kPi)); }

Fundamental ranged(Fundamental f, double lo, double hi) {
  f.lo = lo;
  f.hi = hi;
  return f;
}

Side randomSide(Rng& rng) { return rng.integer(0, 1) ? Side::kMobile : Side::kFixed; }

// A parameter within its bounds (unbounded lengths within ±3), away from the bounds of a polar
// angle (where the azimuth is lost) and from ±π (where an angle wraps).
double drawParameter(const Parameter& p, Rng& rng) {
  const double lo = std::isfinite(p.min) ? p.min : -3.0, hi = std::isfinite(p.max) ? p.max : 3.0;
  const double margin = p.kind == ParamKind::kAngle ? 1e-3 : 0.0;
  return rng.uniform(lo + margin, hi - margin);
}

struct Case {
  std::string name;
  std::function<TranslationPart(Rng&)> make;
  std::vector<Fundamental> (*constraints)(const TranslationPart&);
  bool round_trip_params = true;  // project(translation(t)) == t
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

template <typename S>
std::vector<Fundamental> constraintsOf(const TranslationPart& part) {
  std::vector<Fundamental> out;
  S::eachConstraint(*part.as<S>(), [&](const Fundamental& f) { out.push_back(f); });
  return out;
}

std::vector<Case> cases() {
  auto pp = [](Rng& r, double v) { return Fundamental::pointPoint(r.point(), r.point(), v, 1); };
  auto pl = [](Rng& r, double v) {
    return Fundamental::pointLine(randomSide(r), r.point(), r.point(), r.unit(), v, 1);
  };
  auto pplane = [](Rng& r) {
    return Fundamental::pointPlane(randomSide(r), r.point(), r.point(), r.unit(), 0.0, 1);
  };
  return {
      {"Free", [](Rng&) { return TranslationPart(tr::Free{}); }, &constraintsOf<tr::Free>},
      {"Point", [=](Rng& r) { return TranslationPart(tr::Point(pp(r, 0.0))); },
       &constraintsOf<tr::Point>},
      {"Line", [=](Rng& r) { return TranslationPart(tr::Line(pl(r, 0.0))); },
       &constraintsOf<tr::Line>},
      {"Plane", [=](Rng& r) { return TranslationPart(tr::Plane(pplane(r))); },
       &constraintsOf<tr::Plane>},
      {"Sphere", [=](Rng& r) { return TranslationPart(tr::Sphere(pp(r, r.uniform(0.1, 2)))); },
       &constraintsOf<tr::Sphere>},
      {"Cylinder", [=](Rng& r) { return TranslationPart(tr::Cylinder(pl(r, r.uniform(0.1, 2)))); },
       &constraintsOf<tr::Cylinder>},
      {"LineOfPlanes",
       [=](Rng& r) {
         // Both planes on the same side: their angle is the same for every R.
         Fundamental a = pplane(r), b = pplane(r);
         b.point_side = a.point_side;
         return TranslationPart(tr::LineOfPlanes(a, b));
       },
       &constraintsOf<tr::LineOfPlanes>},
      {"PointOfLinePlane",
       [=](Rng& r) {
         Fundamental a = pl(r, 0.0), b = pplane(r);
         b.point_side = a.point_side;
         return TranslationPart(tr::PointOfLinePlane(a, b));
       },
       &constraintsOf<tr::PointOfLinePlane>},
      {"Ellipse",
       [=](Rng& r) {
         Fundamental a = pl(r, r.uniform(0.1, 2)), b = pplane(r);
         b.point_side = a.point_side;
         return TranslationPart(tr::Ellipse(a, b));
       },
       &constraintsOf<tr::Ellipse>},
      {"EllipseNearCircle",
       [=](Rng& r) {
         // The axis 1e-11 rad from the plane's normal: the in-plane axes come from a cross
         // product of that size, whose rounding must not tilt them off the plane.
         Fundamental a = pl(r, r.uniform(0.1, 2)), b = pplane(r);
         b.point_side = a.point_side;
         b.d = (a.d + 1e-11 * anyPerpendicular(a.d)).normalized();
         return TranslationPart(tr::Ellipse(a, b));
       },
       &constraintsOf<tr::Ellipse>},
      {"Shell", [=](Rng& r) { return TranslationPart(tr::Shell(ranged(pp(r, 0.0), 0.5, 1.5))); },
       &constraintsOf<tr::Shell>},
      {"ThickCylinder",
       [=](Rng& r) { return TranslationPart(tr::ThickCylinder(ranged(pl(r, 0.0), 0.5, 1.5))); },
       &constraintsOf<tr::ThickCylinder>},
      {"Slab", [=](Rng& r) { return TranslationPart(tr::Slab(ranged(pplane(r), -0.5, 0.7))); },
       &constraintsOf<tr::Slab>},
      {"Planes",
       [=](Rng& r) {
         // Two planes (one ranged) and a mobile point on a line: up to three rows, all mobile.
         tr::Planes s;
         Fundamental a = pplane(r), b = ranged(pplane(r), -0.3, 0.4);
         a.point_side = b.point_side = Side::kMobile;
         s.linear.push_back(a);
         s.linear.push_back(b);
         return TranslationPart(s);
       },
       &constraintsOf<tr::Planes>},
      {"BoundedCylinder",
       [=](Rng& r) {
         // One mobile point: its distance from a fixed axis and its height over a fixed plane
         // square to it (the projection is then exact).
         const Vector3d tip = r.point(), axis_point = r.point(), axis = r.unit();
         const Fundamental line =
             ranged(Fundamental::pointLine(Side::kMobile, tip, axis_point, axis, 0.0, 1), 0.3, 0.9);
         const Fundamental plane = ranged(
             Fundamental::pointPlane(Side::kMobile, tip, axis_point, axis, 0.0, 2), -0.2, 0.5);
         return TranslationPart(tr::BoundedCylinder(line, plane));
       },
       &constraintsOf<tr::BoundedCylinder>},
  };
}

class TranslationShape : public ::testing::TestWithParam<Case> {};

TEST_P(TranslationShape, PosesSatisfyTheConstraints) {
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const TranslationPart part = GetParam().make(rng);
    const Matrix3d R = randomRotation(rng);
    double t[6] = {};
    for (int i = 0; i < part.dof(); ++i) t[i] = drawParameter(part.parameter(i), rng);
    const Vector3d T = part.translation(R, t);
    for (const Fundamental& f : GetParam().constraints(part))
      EXPECT_LT(violation(f, R, T), 1e-9 * (1.0 + T.norm())) << GetParam().name << " " << trial;
  }
}

TEST_P(TranslationShape, ProjectingAPointOfTheSetGivesItsParameters) {
  Rng rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const TranslationPart part = GetParam().make(rng);
    const Matrix3d R = randomRotation(rng);
    double t[6] = {}, back[6] = {};
    for (int i = 0; i < part.dof(); ++i) t[i] = drawParameter(part.parameter(i), rng);
    const Vector3d T = part.translation(R, t);
    part.project(R, T, back);
    EXPECT_LT((part.translation(R, back) - T).norm(), 1e-9) << GetParam().name;
    if (GetParam().round_trip_params) {
      for (int i = 0; i < part.dof(); ++i) EXPECT_NEAR(back[i], t[i], 1e-8) << GetParam().name;
    }
    // projectAndPlace: the same parameters and the translation at them.
    double placed_t[6] = {};
    const Vector3d placed = part.projectAndPlace(R, T, placed_t);
    EXPECT_LT((placed - T).norm(), 1e-9) << GetParam().name;
  }
}

// The search places every pose it weighs with projectAndPlace, which a shape may compute its own
// way (BoundedCylinder takes the azimuth's direction from the point, not from its angle): off the
// set as on it, the parameters are project()'s and the translation is translation() at them.
TEST_P(TranslationShape, ProjectAndPlaceIsTheTranslationAtTheProjection) {
  Rng rng(15);
  for (int trial = 0; trial < 200; ++trial) {
    const TranslationPart part = GetParam().make(rng);
    const Matrix3d R = randomRotation(rng);
    const Vector3d X = rng.point(3.0);
    double projected[6] = {}, placed_t[6] = {};
    part.project(R, X, projected);
    const Vector3d placed = part.projectAndPlace(R, X, placed_t);
    for (int i = 0; i < part.dof(); ++i)
      EXPECT_EQ(placed_t[i], projected[i]) << GetParam().name << " " << trial << " θ" << i;
    const Vector3d at = part.translation(R, placed_t);
    EXPECT_LT((placed - at).norm(), 1e-12 * (1.0 + at.norm())) << GetParam().name << " " << trial;
  }
}

TEST_P(TranslationShape, AnExactProjectionIsTheNearestPointOfTheSet) {
  Rng rng(13);
  for (int trial = 0; trial < 100; ++trial) {
    const TranslationPart part = GetParam().make(rng);
    if (!part.projectsExactly()) return;  // the ellipse: affine, not the foot point
    const Matrix3d R = randomRotation(rng);
    const Vector3d X = rng.point(3.0);
    double near[6] = {};
    part.project(R, X, near);
    const double d = (part.translation(R, near) - X).norm();
    // No point of the set, drawn at random, is nearer.
    for (int k = 0; k < 50; ++k) {
      double t[6] = {};
      for (int i = 0; i < part.dof(); ++i) t[i] = drawParameter(part.parameter(i), rng);
      EXPECT_GE((part.translation(R, t) - X).norm(), d - 1e-9) << GetParam().name;
    }
  }
}

TEST_P(TranslationShape, TheSeparableManifoldContainsItsPosesAndNotOthers) {
  Rng rng(14);
  const Tolerance tol;
  for (int trial = 0; trial < 50; ++trial) {
    const TranslationPart part = GetParam().make(rng);
    const SeparableManifold m(manifolds::rotation::Free{}, part);
    EXPECT_EQ(m.dof(), 3 + part.dof());
    Params theta{};
    for (int i = 0; i < m.dof(); ++i) theta[i] = drawParameter(m.parameter(i), rng);
    const Isometry3d X = m.pose(theta);
    EXPECT_TRUE(m.contains(X, tol)) << GetParam().name;
    if (part.dof() == 3) continue;  // every translation is on it
    // Moved off the set along a direction the set does not allow at this rotation.
    bool off = false;
    for (int axis = 0; axis < 3 && !off; ++axis) {
      Isometry3d Y = X;
      Y.translation() += 0.05 * Vector3d::Unit(axis);
      double v = 0.0;
      for (const Fundamental& f : GetParam().constraints(part))
        v = std::max(v, violation(f, Y.linear(), Y.translation()));
      if (v > 1e-3) {
        off = true;
        EXPECT_FALSE(m.contains(Y, tol)) << GetParam().name;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, TranslationShape, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(TranslationPart, NamesAreTheOnesResultsWrite) {
  const Fundamental f = Fundamental::pointPoint(Vector3d::Zero(), Vector3d::Zero(), 0.0, 1);
  EXPECT_STREQ(TranslationPart().name(), "R3");
  EXPECT_STREQ(TranslationPart(tr::Slab(f)).name(), "Box");
  EXPECT_STREQ(TranslationPart(tr::LineOfPlanes(f, f)).name(), "Line");
  EXPECT_STREQ(TranslationPart(tr::PointOfLinePlane(f, f)).name(), "Point");
}

TEST(TranslationPart, SpinInvarianceFollowsTheMobileGeometry) {
  const Vector3d u = Vector3d::UnitZ();
  // A mobile point on the spin axis does not move with the spin; one off it does.
  const auto on = Fundamental::pointPoint(Vector3d(0, 0, 2), Vector3d(1, 2, 3), 0.5, 1);
  const auto off = Fundamental::pointPoint(Vector3d(1e-6, 0, 2), Vector3d(1, 2, 3), 0.5, 1);
  EXPECT_TRUE(TranslationPart(tr::Sphere(on)).invariantUnderSpin(u));
  EXPECT_FALSE(TranslationPart(tr::Sphere(off)).invariantUnderSpin(u));
  EXPECT_TRUE(TranslationPart(tr::Free{}).invariantUnderSpin(u));
}

}  // namespace
}  // namespace relpos::test
