// `inconsistent` only when certain (docs/spec.md §6.4, solver.cpp doubtNarrowConflict): a conflict
// the rules find within 10 tolerances, where the last check would let a branch through, is
// `unhandled`; one beyond stays `inconsistent`; and a feasible problem whose near-parallel planes
// the rules read too narrowly is never `inconsistent`.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "result_checker.hpp"
#include "spec_writer.hpp"

namespace relpos::test {
namespace {

// A tab in a slot: the slot's floor and roof `height` apart, the tab that thick plus `excess`,
// each face on its opposite, both objects placed by `place` (the faces' points off the axis by
// lengths in proportion to the height, so that a scaled copy is the same problem).
Problem tabInSlot(double height, double excess, const Isometry3d& place = Isometry3d::Identity()) {
  const Vector3d z = place.linear() * Vector3d::UnitZ();
  auto at = [&](double h) { return Vector3d(place * Vector3d(30 * height, -20 * height, h)); };
  Problem p;
  p.addFixedFeature("floor", Feature::makePlane(at(0.0), z));
  p.addFixedFeature("roof", Feature::makePlane(at(height), -z));
  p.addMobileFeature("bottom", Feature::makePlane(at(0.0), -z));
  p.addMobileFeature("top", Feature::makePlane(at(height + excess), z));
  p.addConstraint("coincident", "floor", "bottom", 0.0, Orientation::kOpposed);
  p.addConstraint("coincident", "roof", "top", 0.0, Orientation::kOpposed);
  return p;
}

// The slot 10 mm high in metres: its size (the diagonal of the faces' points) is 0.01, the length
// tolerance 1e-11.
constexpr double kHeight = 0.01;
constexpr double kTolerance = 1e-9 * kHeight;

TEST(NarrowConflict, WithinTheToleranceTheTabFits) {
  const Solution s = solve(tabInSlot(kHeight, 0.5 * kTolerance), builtinRegistry());
  EXPECT_EQ(s.status, Status::kSolved) << s.message;
}

TEST(NarrowConflict, AFewTolerancesThickerIsUndecided) {
  for (double k : {3.0, 8.0}) {
    const Solution s = solve(tabInSlot(kHeight, k * kTolerance), builtinRegistry());
    EXPECT_EQ(s.status, Status::kUnhandled) << k << " tolerances: " << s.message;
    EXPECT_NE(s.message.find("undecided: constraints 0, 1 conflict by less than 10 tolerances"),
              std::string::npos)
        << s.message;
    EXPECT_TRUE(s.conflicts.empty());
    EXPECT_TRUE(s.branches.empty());
    EXPECT_FALSE(s.complete);
  }
}

TEST(NarrowConflict, FarThickerIsInconsistent) {
  for (double k : {20.0, 1e3, 1e6}) {
    const Solution s = solve(tabInSlot(kHeight, k * kTolerance), builtinRegistry());
    EXPECT_EQ(s.status, Status::kInconsistent) << k << " tolerances: " << s.message;
    EXPECT_TRUE(s.complete);
    EXPECT_EQ(s.conflicts.size(), 2u);
  }
}

// The verdicts are the problem's, not its frame's or its unit's: moved 1e4 slot heights away and
// turned (no further: the coordinates' rounding would widen the tolerance), scaled by 1e-3 and 1e3
// (the tolerance scales with it).
TEST(NarrowConflict, MovedAndScaledCopiesKeepTheirVerdicts) {
  Isometry3d moved = Isometry3d::Identity();
  moved.linear() = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (double scale : {1e-3, 1.0, 1e3})
    for (bool move : {false, true}) {
      moved.translation() = scale * Vector3d(100, -40, 25);
      const Isometry3d place = move ? moved : Isometry3d::Identity();
      const double h = scale * kHeight, t = scale * kTolerance;
      EXPECT_EQ(solve(tabInSlot(h, 4 * t, place), builtinRegistry()).status, Status::kUnhandled)
          << "scale " << scale;
      EXPECT_EQ(solve(tabInSlot(h, 100 * t, place), builtinRegistry()).status,
                Status::kInconsistent)
          << "scale " << scale;
    }
}

// A seed hunt's case (property tests, offset 5043, "two plane contacts an angle from parallel"):
// each pair of planes 1e-9 rad from parallel, the mobile's a rigid copy of the fixed ones, so the
// known pose below meets both contacts to rounding. The rules read the planes' distance where the
// problem is centred, while at the known pose the contacts lie 1.6 from there, where planes 1e-9
// apart part by 1.6e-9 more; the span angle then differs from the parallelism's by 8e-9 rad,
// where 5e-9 was allowed, and the answer was a false `inconsistent`.
TEST(NarrowConflict, NearlyParallelPlaneContactsAreNeverInconsistent) {
  Problem p;
  p.addFixedFeature(
      "F1",
      Feature::makePlane(Vector3d(-2.356344155818593, 1.0364193044033256, -4.161724538469354),
                         Vector3d(-0.5880664880466462, 0.08029127245220535, 0.8048174434022224)));
  p.addFixedFeature(
      "F3",
      Feature::makePlane(Vector3d(-2.2881456730588194, 1.006628291632882, -4.108921011198988),
                         Vector3d(-0.5880664888105701, 0.0802912727239544, 0.8048174428169255)));
  p.addMobileFeature(
      "M0",
      Feature::makePlane(Vector3d(0.10098298032916456, 0.9025281416950353, 0.3637634544947309),
                         Vector3d(0.9219199520456347, -0.3335051990765755, 0.1970732965398112)));
  p.addMobileFeature(
      "M2",
      Feature::makePlane(Vector3d(0.1592764137594682, 1.0646232244927099, 0.36537540769017085),
                         Vector3d(0.9219199519010959, -0.33350519984471527, 0.19707329591605666)));
  p.addConstraint("coincident", "F1", "M0", 0.0, Orientation::kOpposed);
  p.addConstraint("coincident", "F3", "M2", 0.0, Orientation::kOpposed);
  p.fixed.pose.translation() =
      Vector3d(-1.7309218709139504, -1.576024650226279, 1.6212314589249703);
  p.fixed.pose.linear() = Eigen::Quaterniond(0.7634218672642124, 0.45800470491157486,
                                             -0.3641189219943935, -0.2735619737962958)
                              .toRotationMatrix();
  p.mobile.pose.translation() =
      Vector3d(1.6022702196624632, -0.8618541620127353, 1.5872931783099666);
  p.mobile.pose.linear() = Eigen::Quaterniond(-0.4609492783862834, 0.30709915459906495,
                                              -0.3462959290238173, 0.7571624670711271)
                               .toRotationMatrix();
  Isometry3d known = Isometry3d::Identity();
  known.translation() = Vector3d(0.2742676838683744, 0.18953220649932678, 0.4654911371061736);
  known.linear() = Eigen::Quaterniond(0.8873995555744447, -0.37754382035669154, 0.2402740415388778,
                                      0.11068458537359996)
                       .toRotationMatrix();
  // The premise: the known pose meets both contacts (the evaluator, written from the spec).
  ASSERT_LT(worstViolation(p, known), 1e-12);
  const Solution s = solve(p, builtinRegistry());
  EXPECT_NE(s.status, Status::kInconsistent) << s.message;
}

// A spec (JSON text) whose known pose, given as position and quaternion (w, x, y, z), meets every
// constraint by the tests' evaluator: the solver must not call it inconsistent.
void expectNeverInconsistent(const char* spec, const Vector3d& position,
                             const Eigen::Quaterniond& orientation) {
  const ParseResult r = parseSpec(spec, builtinRegistry());
  ASSERT_TRUE(r.problem);
  Isometry3d known = Isometry3d::Identity();
  known.translation() = position;
  known.linear() = orientation.toRotationMatrix();
  ASSERT_LT(worstViolation(*r.problem, known), 1e-12);  // the premise
  const Solution s = solve(*r.problem, builtinRegistry());
  EXPECT_NE(s.status, Status::kInconsistent) << s.message;
}

// Another (offset 5092, "two line coincidences meeting at an angle"): lines 1e-9 rad from parallel
// read as parallel, their separation where the problem is centred. The wider problem's branch
// breaks the second coincidence by 28 tolerances at its reference parameters, where the lines
// are 2 apart from the contacts; along the branch, where the contacts lie, it meets it: the
// conflict is sought along each branch, not at one pose.
TEST(NarrowConflict, NearlyParallelLineCoincidencesAreNeverInconsistent) {
  expectNeverInconsistent(
      R"spec({"relpos": 1, "name": "degenerate-13", "units": {"angle": "rad"}, "fixed": {"name": "base", "pose": {"position": [-0.9561799448800243, -1.5156401315614558, 0.20808963833874605], "orientation": [-0.4245818749591102, 0.4165858692312691, 0.3325527103466732, 0.7318436580678389]}, "features": {"F1": {"line": {"point": [1.6272467001213875, -0.2820187432566747, 4.133697044792326], "direction": [-0.597662198950869, -0.7387767764119342, -0.3114623100466617]}}, "F3": {"line": {"point": [1.6544135351822886, -0.24843752058743956, 4.147854615886531], "direction": [-0.5976621984457071, -0.7387767770605967, -0.31146230947740916]}}, "f2": {"line": {"point": [0.30722618389823786, -2.258667748829062, 1.7387104034735765], "direction": [-0.3143442065133775, 0.943794025178759, -0.10217904808888623]}}}}, "mobile": {"name": "part", "pose": {"position": [1.4228090761127357, 1.8819549888360285, -1.7847718075884473], "orientation": [0.7554111798699776, 0.22846195083967588, -0.3478382624425454, 0.5061300519895344]}, "features": {"M0": {"line": {"point": [0.8853256583529054, 1.0894626984269475, -1.0126826534516775], "direction": [0.22815584884428924, 0.20108532427423984, -0.9526329833675014]}}, "M2": {"line": {"point": [0.8972240417461854, 1.0999493480218825, -1.0623626961629737], "direction": [0.2281558489843693, 0.2010853252357201, -0.9526329831309992]}}, "m2": {"line": {"point": [-0.6843855254854969, 0.5537207073980386, -0.8018114269629824], "direction": [-0.2909447759395885, 0.8032969657125276, -0.519677902388113]}}}}, "constraints": [{"type": "coincident", "fixed": "F1", "mobile": "M0", "orientation": "aligned"}, {"type": "coincident", "fixed": "F3", "mobile": "M2", "orientation": "aligned"}, {"type": "angle", "fixed": "f2", "mobile": "m2", "value": 2.795281019190247, "orientation": "aligned"}]})spec",
      Vector3d(0.5469183190766085, 1.6601013017895174, -0.16272003754342057),
      Eigen::Quaterniond(-0.35999658631447334, 0.6189838637568121, 0.6224883358224665,
                         0.3158634293735038));
}

// A third (offset 7059, the same family): the contacts lie 1.3 along lines 1e-9 rad from
// parallel, 70 times the problem's size (its points span 0.019), where the lines have drifted
// 1.3e-9 apart: the span read at the centre was 7e-8 rad off, not the 6e-9 it claimed, and even
// the 10-times-wider problem was inconsistent. pl+pl/parallel-span now reads only lines parallel
// to rounding.
TEST(NarrowConflict, LineCoincidencesFarAlongNearlyParallelLinesAreNeverInconsistent) {
  expectNeverInconsistent(
      R"spec({"relpos":1,"name":"degenerate-3","units":{"angle":"rad"},"fixed":{"name":"base","pose":{"position":[1.064045510732138,-0.05843818449770288,-1.4680921756815073],"orientation":[0.3784142378007964,0.3853860119320051,0.7324960263437413,0.41440301377694605]},"features":{"F1":{"line":{"point":[-0.31554469365473425,3.78936139891272,-1.312666933494809],"direction":[0.3973919573540703,0.10501165877006413,0.9116206358747372]}},"F3":{"line":{"point":[-0.321280305694836,3.787845750764614,-1.3258244763122973],"direction":[-0.3973919578866039,-0.10501165955270936,-0.9116206355524415]}},"f2":{"plane":{"point":[1.9390581360177928,2.0487326320435564,1.6243654632852922],"normal":[-0.3849510930825839,-0.4299257531156351,0.8166862939602194]}}}},"mobile":{"name":"part","pose":{"position":[-0.6128202166745589,-0.8163653442120389,-1.6679749955397674],"orientation":[0.26762080414947836,-0.34205158548319853,0.5302668273090223,0.7281462146509038]},"features":{"M0":{"line":{"point":[-1.275040368940285,2.330680356098463,-0.8469613245028034],"direction":[-0.13318966243082414,0.5284892747643987,0.8384268604240701]}},"M2":{"line":{"point":[-1.277555449206006,2.3406600564829825,-0.8311289340758864],"direction":[-0.1331896627382947,0.5284892755465893,0.8384268598821847]}},"m2":{"plane":{"point":[-0.9004641562397298,-0.3602762240136146,0.5690237788285266],"normal":[-0.19780732510272808,0.32770534845477156,-0.923840606776862]}}}},"constraints":[{"type":"coincident","fixed":"F1","mobile":"M0","orientation":"aligned"},{"type":"coincident","fixed":"F3","mobile":"M2","orientation":"either"},{"type":"angle","fixed":"f2","mobile":"m2","value":2.8823401673627393,"orientation":"aligned"}]})spec",
      Vector3d(1.0324730261539758, -1.6980437726397017, -0.41436710692913303),
      Eigen::Quaterniond(0.64043124479094415, 0.12729443994382189, 0.64564901941152264,
                         0.39595617180169018));
}

// A fourth (offset 41, the same family, two coincidences alone): the mobile lines 1e-9 rad apart
// and the fixed ones too, so one parallelism fixes the rotation but for a turn about the first
// fixed line, and both coincidences were read as invariant under that turn (the revolved branch's
// derived set, solved at one turn). They are only within the tolerance: at that turn the second
// line was 5.7e-10 off where the first put its contact, and the problem inconsistent. Lines
// tilted beyond rounding from the axis are not invariant about it (derived_sets.cpp).
TEST(NarrowConflict, LineCoincidencesTiltedFromTheTurnsAxisAreNeverInconsistent) {
  expectNeverInconsistent(
      R"spec({"relpos":1,"name":"degenerate-12","units":{"angle":"rad"},"fixed":{"name":"base","pose":{"position":[-1.0797151059948273,-0.3183710413733061,-0.5638667841254821],"orientation":[-0.3659943470062804,-0.021688692825686327,0.24964294843898877,0.8962455784312957]},"features":{"F1":{"line":{"point":[2.393769517766246,-1.2500419054847005,-0.6004716928052486],"direction":[-0.04810575721286284,-0.2530792485296477,0.9662487930583128]}},"F3":{"line":{"point":[2.37059824648452,-1.371943487941238,-0.13505519748367634],"direction":[-0.04810575771481376,-0.25307924768717593,0.9662487932539822]}}}},"mobile":{"name":"part","pose":{"position":[-1.6612226445846012,-1.778616774930938,-1.743181957996661],"orientation":[-0.021295324127109203,-0.17200832041344868,-0.356986273034897,0.9178891260623582]},"features":{"M0":{"line":{"point":[1.0230214028715297,1.4555286953720332,0.8798001129799102],"direction":[0.9055850057224626,0.0812582009780448,0.4163086621540068]}},"M2":{"line":{"point":[1.2711085153701125,1.4777895675451949,0.9938488368585425],"direction":[0.9055850055149389,0.08125820020693396,0.41630866275593864]}}}},"constraints":[{"type":"coincident","fixed":"F1","mobile":"M0","orientation":"aligned"},{"type":"coincident","fixed":"F3","mobile":"M2","orientation":"aligned"}]})spec",
      Vector3d(0.50713175060192972, -1.202543947202853, -0.94965434825722062),
      Eigen::Quaterniond(0.50528978252590162, -0.41361280315403265, -0.59853489119919001,
                         -0.46407183577455369));
}

// A constructed case: fixed features and mobile points (each object's "features" members, JSON)
// under `constraints` (a JSON array's members), both frames at the world's origin, which the
// known pose — translated by `position`, not turned — meets: never `inconsistent`.
void expectTranslatedPoseFeasible(const std::string& fixed, const std::string& mobile,
                                  const std::string& constraints, const Vector3d& position) {
  const std::string spec = R"({"relpos": 1, "name": "constructed", "units": {"angle": "rad"},
      "fixed": {"name": "base", "features": {)" +
                           fixed + R"(}}, "mobile": {"name": "part", "features": {)" + mobile +
                           R"(}}, "constraints": [)" + constraints + "]}";
  expectNeverInconsistent(spec.c_str(), position, Eigen::Quaterniond::Identity());
}

// The same for planes and for a line and a plane (by construction): two points 1e-7 closer
// together than the parallel planes (or the line and the plane) are apart where the problem is
// centred, which are tilted 1e-9 rad: 100 away they are close enough. pplane+pplane and
// pl+pplane read only features parallel to rounding as a span or a conflict.
TEST(NarrowConflict, PointsOnPlanesTiltedWithinTheToleranceAreNeverInconsistent) {
  expectTranslatedPoseFeasible(
      R"("S": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
         "P": {"plane": {"point": [0, 0, 1], "normal": [-1e-9, 0, 1]}})",
      R"("a": {"point": [0, 0, 0]}, "b": {"point": [0, 0, 0.9999999]})",
      R"({"type": "coincident", "fixed": "S", "mobile": "a"},
         {"type": "coincident", "fixed": "P", "mobile": "b"})",
      Vector3d(-100, 0, 0));
}

TEST(NarrowConflict, PointsOnALineAndAPlaneTiltedWithinTheToleranceAreNeverInconsistent) {
  const char* const line_and_plane =
      R"("K": {"line": {"point": [0, 0, 1], "direction": [1, 0, 1e-9]}},
         "S": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})";
  expectTranslatedPoseFeasible(line_and_plane,
                               R"("a": {"point": [0, 0, 0.9999999]}, "b": {"point": [0, 0, 0]})",
                               R"({"type": "coincident", "fixed": "K", "mobile": "a"},
         {"type": "coincident", "fixed": "S", "mobile": "b"})",
                               Vector3d(-100, 0, 0));
  // One point a distance from the line and on the plane: on the long ellipse they meet in 100
  // away.
  expectTranslatedPoseFeasible(
      line_and_plane, R"("a": {"point": [0, 0, 0]})",
      R"({"type": "distance", "fixed": "K", "mobile": "a", "value": 0.9999999},
         {"type": "coincident", "fixed": "S", "mobile": "a"})",
      Vector3d(-100, 0, 0));
}

// One point on two lines that cross at an angle within the tolerance but beyond rounding (seed
// offset 7505), or on a line and a plane it crosses so: one line (or a line in the plane) where
// the problem is centred, they drift apart along their length, so the point is not anywhere on
// one of them (read so, the point slid 900 along it, to where the other was 9e-7 away); nor is a
// point 0.1 from the line and on the plane on two lines of it. Whatever the answer, every pose of
// every branch, drawn 10,000 about its reference parameters, meets every constraint.
TEST(NarrowConflict, APointOnFeaturesCrossingWithinTheToleranceIsNotOnOneLine) {
  struct Case {
    const char* fixed;  // `T` stands for the tilt
    const char* constraints;
  };
  const Case cases[] = {
      {R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, 0]}},
          "L": {"line": {"point": [0, 0, 0], "direction": [1, T, 0]}})",
       R"({"type": "coincident", "fixed": "K", "mobile": "a"},
          {"type": "coincident", "fixed": "L", "mobile": "a"})"},
      {R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, T]}},
          "S": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})",
       R"({"type": "coincident", "fixed": "K", "mobile": "a"},
          {"type": "coincident", "fixed": "S", "mobile": "a"})"},
      {R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, T]}},
          "S": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}})",
       R"({"type": "distance", "fixed": "K", "mobile": "a", "value": 0.1},
          {"type": "coincident", "fixed": "S", "mobile": "a"})"},
  };
  for (const Case& c : cases)
    for (const std::string tilt : {"1e-9", "1e-11"}) {
      std::string fixed = c.fixed;
      fixed.replace(fixed.find('T'), 1, tilt);
      const std::string spec = R"({"relpos": 1, "name": "crossing", "units": {"angle": "rad"},
          "fixed": {"name": "base", "features": {)" +
                               fixed + R"(}},
          "mobile": {"name": "part", "features": {"a": {"point": [0.3, 0.2, 0.1]}}},
          "constraints": [)" + c.constraints +
                               "]}";
      const ParseResult r = parseSpec(spec, builtinRegistry());
      ASSERT_TRUE(r.problem) << spec;
      const Problem& p = *r.problem;
      const Solution s = solve(p, builtinRegistry());
      EXPECT_NE(s.status, Status::kInconsistent) << spec;  // where they cross meets both
      std::mt19937_64 rng(7505);
      for (const Branch& b : s.branches)
        for (int k = 0; k < 2000; ++k) {
          const Manifold& m = *b.manifold;
          const Isometry3d X = m.pose(sampleParameters(m, referenceParams(m), 1e4, rng));
          ASSERT_LE(worstViolation(p, X), 1e-9) << m.describe() << "\n" << spec;
        }
    }
}

// And for Somani's ranges on one point (by construction): two slabs, a thick cylinder and a
// plane, two thick cylinders, each pair parallel within 1e-9 rad and 1e-7 apart where the
// problem is centred, overlap 200 away.
TEST(NarrowConflict, RangesOnFeaturesTiltedWithinTheToleranceAreNeverInconsistent) {
  const char* const point = R"("a": {"point": [0, 0, 0]})";
  expectTranslatedPoseFeasible(
      R"("S": {"plane": {"point": [0, 0, 0], "normal": [0, 0, 1]}},
         "P": {"plane": {"point": [0, 0, 0], "normal": [-1e-9, 0, 1]}})",
      point,
      R"({"type": "distance", "fixed": "S", "mobile": "a", "min": 0.5, "max": 1},
         {"type": "distance", "fixed": "P", "mobile": "a", "min": 1.0000001, "max": 2})",
      Vector3d(-200, 0, 1));
  expectTranslatedPoseFeasible(
      R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, 1e-9]}},
         "S": {"plane": {"point": [0, 0, 2], "normal": [0, 0, 1]}})",
      point,
      R"({"type": "distance", "fixed": "K", "mobile": "a", "min": 0.5, "max": 1.9999999},
         {"type": "coincident", "fixed": "S", "mobile": "a"})",
      Vector3d(200, 0, 2));
  expectTranslatedPoseFeasible(
      R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, 0]}},
         "L": {"line": {"point": [0, 0, 0], "direction": [1, 0, 1e-9]}})",
      point,
      R"({"type": "distance", "fixed": "K", "mobile": "a", "min": 0.5, "max": 1},
         {"type": "distance", "fixed": "L", "mobile": "a", "min": 1.0000001, "max": 2})",
      Vector3d(-200, 0, 1));
}

// Two nearly coaxial lines (1e-9 rad, through one point): one point 1 from the first and
// 1 + 1e-7 from the second, and two points 0.5 apart, one on the first and the other 0.5 + 1e-7
// from the second, fit 100 away. pl+pl calls a conflict of lines parallel only within the
// tolerance only from their least distance.
TEST(NarrowConflict, DistancesFromNearlyCoaxialLinesAreNeverInconsistent) {
  const char* const nearly_coaxial =
      R"("K": {"line": {"point": [0, 0, 0], "direction": [1, 0, 0]}},
         "L": {"line": {"point": [0, 0, 0], "direction": [1, 0, 1e-9]}})";
  expectTranslatedPoseFeasible(nearly_coaxial, R"("a": {"point": [0, 0, 0]})",
                               R"({"type": "distance", "fixed": "K", "mobile": "a", "value": 1},
         {"type": "distance", "fixed": "L", "mobile": "a", "value": 1.0000001})",
                               Vector3d(-100, 0, 1));
  expectTranslatedPoseFeasible(nearly_coaxial,
                               R"("a": {"point": [0, 0, 0]}, "b": {"point": [0, 0, 0.5]})",
                               R"({"type": "coincident", "fixed": "K", "mobile": "a"},
         {"type": "distance", "fixed": "L", "mobile": "b", "value": 0.5000001})",
                               Vector3d(-100, 0, 0));
}

// The same, random (seeded): two fixed features (planes or lines) 1e-10 to 1e-9 rad from
// parallel, and two contacts on them (on the feature, a distance from it, or within a range of
// distances; two mobile points or one) that a known pose meets 20 to 200 problem sizes along
// them, where the features have drifted 2e-9 to 2e-7 apart. The initial pose puts the mobile
// points where the problem is centred. Never `inconsistent`, and whatever is solved holds there.
TEST(NarrowConflict, RandomContactsFarAlongNearlyParallelFeaturesAreNeverInconsistent) {
  Rng rng(44018);
  enum Kind { kOn, kValue, kRange };
  int solved = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const bool a_line = rng.integer(0, 1) == 1, b_line = rng.integer(0, 1) == 1;
    // A's normal (plane) or direction (line) u, B's tilted from it by θ toward w; a line and a
    // plane: the line's direction w, ⊥ the plane's normal u but for a tilt of θ. t: the direction
    // along both features in which they drift apart.
    const Vector3d u = rng.unit(), w = rng.perpendicular(u);
    const double theta = std::pow(10.0, rng.uniform(-10.0, -9.0));
    const Vector3d tilted = (u + theta * w).normalized();
    const Vector3d u_a = a_line && !b_line ? w : u;
    const Vector3d u_b =
        a_line == b_line || a_line ? tilted : Vector3d((w + theta * u).normalized());
    const Vector3d t = a_line && b_line ? u : w;
    const Vector3d a0 = rng.point(1.0), b0 = a0 + rng.uniform(0.0, 1.0) * rng.unit();
    const double far = rng.uniform(20.0, 200.0) * (rng.integer(0, 1) ? 1.0 : -1.0);
    const bool one_point = rng.integer(0, 2) == 0;
    const Kind kind_a = Kind(rng.integer(0, 2));
    const Kind kind_b = one_point ? Kind(rng.integer(1, 2)) : Kind(rng.integer(0, 2));
    // A contact near the far location of feature (q, d): on it, or off it by up to 0.5.
    auto contactPoint = [&](bool line, const Vector3d& q, const Vector3d& d, Kind k) {
      const Vector3d x = q + far * t + 0.5 * rng.unit();
      const double off = k == kOn ? 0.0 : rng.uniform(0.0, 0.5);
      return line ? Vector3d(q + (x - q).dot(d) * d + off * rng.perpendicular(d))
                  : Vector3d(x - (x - q).dot(d) * d + (rng.integer(0, 1) ? off : -off) * d);
    };
    const Vector3d P = contactPoint(a_line, a0, u_a, kind_a);
    const Vector3d Q = one_point ? P : contactPoint(b_line, b0, u_b, kind_b);
    const Isometry3d known = rng.pose();
    Problem p;
    p.addFixedFeature("A", a_line ? Feature::makeLine(a0, u_a) : Feature::makePlane(a0, u_a));
    p.addFixedFeature("B", b_line ? Feature::makeLine(b0, u_b) : Feature::makePlane(b0, u_b));
    p.addMobileFeature("p", Feature::makePoint(known.inverse() * P));
    if (!one_point) p.addMobileFeature("q", Feature::makePoint(known.inverse() * Q));
    // The initial pose: the known one moved back along the features, to the centre.
    p.mobile.pose = known;
    p.mobile.pose.translation() -= far * t;
    auto constrain = [&](const char* fixed, const char* mobile, bool line, const Vector3d& q,
                         const Vector3d& d, const Vector3d& x, Kind k) {
      if (k == kOn) return p.addConstraint(ConstraintSpec("coincident", fixed, mobile));
      // Point-line distances are unsigned; point-plane ones signed along the normal.
      const double v = line ? (x - q - (x - q).dot(d) * d).norm() : (x - q).dot(d);
      if (k == kValue) return p.addConstraint(ConstraintSpec("distance", fixed, mobile).value(v));
      const double lo = v - rng.uniform(0.0, 0.3), hi = v + rng.uniform(0.0, 0.3);
      return p.addConstraint(
          ConstraintSpec("distance", fixed, mobile).range(line ? std::max(0.0, lo) : lo, hi));
    };
    constrain("A", "p", a_line, a0, u_a, P, kind_a);
    constrain("B", one_point ? "p" : "q", b_line, b0, u_b, Q, kind_b);
    ASSERT_LT(worstViolation(p, known), 1e-9) << "trial " << trial;  // the premise
    const Solution s = solve(p, builtinRegistry());
    EXPECT_NE(s.status, Status::kInconsistent) << "trial " << trial << ": " << s.message << "\n"
                                               << written(p).text;
    if (s.status != Status::kSolved) continue;
    ++solved;
    const CheckReport rep = checkSolution(p, s, CheckOptions{});
    EXPECT_TRUE(rep.violating.empty() && rep.non_finite.empty())
        << "trial " << trial << ": " << rep.summary() << written(p).text;
  }
  RecordProperty("solved", solved);
}

// Seed offset 7449 ("coincident line(f)-plane(m) + skew distance line-line + coincident
// line-line either", world moved 1e6 and rotated): one alternative puts a point on two lines, a
// given one and one derived from the plane, parallel and apart. Unmoved they are exactly
// parallel and conflict; moved, the derived one is 9e-17 rad off, and pl+pl looked for where
// they cross (1e8 away, "within the tolerance"), found it too ill-conditioned and deferred: the
// problem was `unhandled`. Lines parallel to rounding now conflict as parallel lines do.
TEST(NarrowConflict, LinesParallelToRoundingConflictAsParallelLines) {
  const char* const specs[] = {
      R"spec({"relpos":1,"name":"generated-3-207","units":{"angle":"rad"},"fixed":{"name":"base","pose":{"position":[0.0,2.0,2.0],"orientation":[1.0,0.0,0.0,-0.0]},"features":{"f0":{"line":{"point":[-3.1822249708488557,-1.7900131356054567,1.0],"direction":[0.7175197947620766,0.696538113906617,0.0]}},"f1":{"line":{"point":[-5.0,0.22438295275328923,0.9949309555257955],"direction":[0.0,0.0,1.0]}},"f2":{"line":{"point":[-3.0,0.9336943259644777,0.0],"direction":[0.0,1.0,0.0]}}}},"mobile":{"name":"part","pose":{"position":[-1.0,2.0,-2.0],"orientation":[0.0,0.0,1.0,0.0]},"features":{"m0":{"plane":{"point":[-2.0,-2.0,0.0],"normal":[0.0,0.0,-1.0]}},"m1":{"line":{"point":[-1.0,0.0,-1.0],"direction":[0.0,-1.0,0.0]}}}},"constraints":[{"type":"coincident","fixed":"f0","mobile":"m0","orientation":"aligned"},{"type":"distance","fixed":"f1","mobile":"m1","value":2.0,"orientation":"aligned","parallel":false},{"type":"coincident","fixed":"f2","mobile":"m1","orientation":"either"}]})spec", R"spec({"relpos":1,"name":"generated-3-207","units":{"angle":"rad"},"fixed":{"name":"base","pose":{"position":[285716.57064106973,-428573.02239661344,857143.3458461127],"orientation":[-0.5403023058681397,0.7479742087181303,0.373987104359065,0.09349677608976624]},"features":{"f0":{"line":{"point":[-3.1822249708488557,-1.7900131356054567,1.0],"direction":[0.7175197947620766,0.6965381139066171,0.0]}},"f1":{"line":{"point":[-5.0,0.22438295275328923,0.9949309555257955],"direction":[0.0,0.0,1.0]}},"f2":{"line":{"point":[-3.0,0.9336943259644777,0.0],"direction":[0.0,1.0,0.0]}}}},"mobile":{"name":"part","pose":{"position":[285715.91224127007,-428569.6420715538,857141.0787086675],"orientation":[0.373987104359065,-0.09349677608976624,0.5403023058681397,0.7479742087181303]},"features":{"m0":{"plane":{"point":[-2.0,-2.0,0.0],"normal":[0.0,0.0,-1.0]}},"m1":{"line":{"point":[-1.0,0.0,-1.0],"direction":[0.0,-1.0,0.0]}}}},"constraints":[{"type":"coincident","fixed":"f0","mobile":"m0","orientation":"aligned"},{"type":"distance","fixed":"f1","mobile":"m1","value":2.0,"orientation":"aligned","parallel":false},{"type":"coincident","fixed":"f2","mobile":"m1","orientation":"either"}]})spec"};
  std::size_t branches[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const ParseResult r = parseSpec(specs[k], builtinRegistry());
    ASSERT_TRUE(r.problem);
    const Solution s = solve(*r.problem, builtinRegistry());
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    branches[k] = s.branches.size();
    const CheckReport rep = checkSolution(*r.problem, s, CheckOptions{});
    EXPECT_TRUE(rep.violating.empty() && rep.non_finite.empty()) << rep.summary();
  }
  EXPECT_EQ(branches[1], branches[0]);  // the same problem, moved
}

}  // namespace
}  // namespace relpos::test
