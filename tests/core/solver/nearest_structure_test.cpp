// The nearest pose by structure (issue 18), on the bundled examples, scenarios and tasks and on
// random single and paired constraints built around known poses (fixed seeds):
// - a branch whose every parameter has a closed form (Manifold::closedFormParams: a spin the
//   translation does not move with, e.g. a face on a face turned about its normal, and the
//   translation given the rotation) has its nearest pose at once, and it is the global one: no
//   pose sampled anywhere over the branch's domain is nearer;
// - a pose whose rotation an exact branch reaches, moved off the branch (the kink of the metric:
//   the rotation distance zero, only the position moves), gets a nearest pose no farther than that
//   move, no sampled pose around it nearer, and where the search stopped on the kink's
//   certificate (settleOnRotationKink) the certificate holds again at the answer; so does a pose
//   whose rotation is also a small ε off the branch's (the kink rounded over ε).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "brent_minimum.hpp"
#include "kink_certificate.hpp"
#include "nearest_eval.hpp"
#include "nearest_one_angle.hpp"
#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/solver.hpp"
#include "relpos/io/spec_reader.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {

std::vector<Problem> bundledProblems() {
  std::vector<Problem> v;
  for (const char* sub : {"/examples", "/scenarios", "/tasks"}) {
    const std::string dir = std::string(RELPOS_DATA_DIR) + sub;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".json" && e.path().filename() != "expected.json")
        files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      ParseResult r = parseSpecFile(f.string(), builtinRegistry());
      if (r.problem) v.push_back(*r.problem);
    }
  }
  return v;
}

// Every kind of single constraint, and pairs of them, around known poses.
std::vector<Problem> randomProblems() {
  std::vector<Problem> v;
  Rng rng(20261205);
  for (int round = 0; round < 6; ++round) {
    const bool grid = round % 2 == 1;
    for (const SingleKind& kind : singleKinds()) {
      KnownProblem kp = emptyKnownProblem(rng, grid);
      addConstraint(kp, kind, rng, grid);
      if (round >= 2) {
        const auto& kinds = singleKinds();
        addConstraint(kp, kinds[rng.integer(0, static_cast<int>(kinds.size()) - 1)], rng, grid);
      }
      v.push_back(kp.problem);
    }
  }
  return v;
}

// Every problem with its solution, solved once for the suite.
const std::vector<std::pair<Problem, Solution>>& solvedProblems() {
  static const std::vector<std::pair<Problem, Solution>> solved = [] {
    std::vector<Problem> v = bundledProblems(), r = randomProblems();
    v.insert(v.end(), r.begin(), r.end());
    std::vector<std::pair<Problem, Solution>> out;
    for (const Problem& p : v) out.emplace_back(p, solve(p, builtinRegistry()));
    return out;
  }();
  return solved;
}

// fn(problem, branch) for every branch of every problem, until an assertion in fn fails.
template <typename Fn>
void forEachBranch(Fn fn) {
  for (const auto& [p, s] : solvedProblems())
    for (const Branch& b : s.branches) {
      fn(p, b);
      if (::testing::Test::HasFatalFailure()) return;
    }
}

// settleOnRotationKink with the manifold's own parameters.
bool settle(const Manifold& m, const Isometry3d& X, Params* best, double* best_d) {
  Parameter par[kMaxDof];
  for (int i = 0; i < m.dof(); ++i) par[i] = m.parameter(i);
  return detail::settleOnRotationKink(m, X, par, best, best_d);
}

// θ moved by up to w along each parameter, kept within its bounds: a neighbourhood, where
// sampleParameters draws over a bounded parameter's whole range.
Params nearby(const Manifold& m, Params t, double w, std::mt19937_64& rng) {
  for (int i = 0; i < m.dof(); ++i) {
    const Parameter p = m.parameter(i);
    t[i] = detail::clampParam(p, t[i] + std::uniform_real_distribution<double>(-w, w)(rng));
  }
  return t;
}

// A random unit vector, a normal draw a coordinate. `normal` is the caller's: it caches every
// second draw, and the counts the tests quote were measured with the caller's own.
Vector3d randomDirection(std::normal_distribution<double>& normal, std::mt19937_64& rng) {
  return Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

bool allClosedForm(const Manifold& m) { return m.dof() > 0 && detail::allParamsClosedForm(m); }

TEST(NearestStructure, AllClosedFormBranchesAreGloballyNearest) {
  std::mt19937_64 rng(181);
  int branches = 0, spins = 0, separated = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    if (!allClosedForm(m)) return;
    ++branches;
    spins += m.rotationalDof() > 0;
    // More than a spin: only a translation that does not move with the rotation (its mobile
    // points at the mobile origin: a torch tip) lets the rotation's projection be the nearest.
    separated += m.rotationalDof() > 1;
    const NearestPose n = nearestOnBranch(b, p.mobile.pose);
    // Over the whole domain (an unbounded length within ±10 of the nearest pose's).
    for (int k = 0; k < 2000; ++k) {
      const Params t = sampleParameters(m, n.parameters, 10.0, rng);
      ASSERT_GE(poseDistance(m.pose(t), p.mobile.pose), n.distance - 1e-9)
          << p.name << " " << m.describe();
    }
  });
  EXPECT_GT(branches, 40);
  EXPECT_GT(spins, 10);  // branches whose rotation is set in closed form too
  EXPECT_GT(separated, 0);
}

TEST(NearestStructure, NearestGlobalOnlyWithAProof) {
  // Said global: no pose sampled over the whole domain is nearer. A pose on the branch is its own
  // nearest, proven; one off a branch the search had to cross is not said global.
  std::mt19937_64 rng(183);
  int said = 0, searched_off = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    const NearestPose n = nearestOnBranch(b, p.mobile.pose);
    if (n.global) {
      ++said;
      for (int k = 0; k < 500; ++k) {
        const Params t = sampleParameters(m, n.parameters, 10.0, rng);
        ASSERT_GE(poseDistance(m.pose(t), p.mobile.pose), n.distance - 1e-9)
            << p.name << " " << m.describe();
      }
    }
    if (m.dof() == 0 || !b.exact) return;
    const Isometry3d on = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
    EXPECT_TRUE(nearestOnBranch(b, on).global) << p.name << " " << m.describe();
    // (Nor one whose rotation X reaches, its position coupled to the rotation by at most 1 a
    // radian: that is proven, NearestKeptRotation.*.)
    const bool keeps =
        m.rotationCoupling() <= 1.0 && rotationDistance(n.pose.linear(), p.mobile.pose.linear()) <=
                                           64 * std::numeric_limits<double>::epsilon();
    if (!allClosedForm(m) && !keeps && n.distance > 1e-6) {
      EXPECT_FALSE(n.global) << p.name << " " << m.describe();
      ++searched_off;
    }
  });
  EXPECT_GT(said, 40);
  EXPECT_GT(searched_off, 40);
}

TEST(NearestStructure, TheSearchWeighsAPoseAsThePoseWithItsClosedForms) {
  // Manifold::searchDistance may skip the closed-form spin (the angle between the spun axis's two
  // directions is the least over the spin) but must weigh every θ as poseWithTail's pose, for X
  // far from the branch and just off it (where the angle is small and a shortcut's rounding
  // shows).
  std::mt19937_64 rng(1812);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int branches = 0, shortcut = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    if (m.closedFormParams() == 0u || detail::allParamsClosedForm(m)) return;
    ++branches;
    bool differs = false;
    for (int k = 0; k < 60; ++k) {
      Isometry3d X = p.mobile.pose;
      if (k % 2 == 1) {  // a pose of the branch moved by up to 1e-3 (rad and length)
        X = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
        const Vector3d w(unit(rng), unit(rng), unit(rng));
        X.linear() = X.linear() * Eigen::AngleAxisd(1e-3 * unit(rng), w.normalized()).matrix();
        X.translation() += 1e-3 * Vector3d(unit(rng), unit(rng), unit(rng));
      }
      Params fast_t = sampleParameters(m, referenceParams(m), 1.0, rng), full_t = fast_t;
      const double fast = m.searchDistance(X, &fast_t);
      const double full = poseDistance(m.poseWithTail(X, &full_t), X);
      ASSERT_NEAR(fast, full, 1e-9 * (1.0 + full)) << p.name << " " << m.describe();
      differs = differs || fast != full;
    }
    shortcut += differs;
  });
  EXPECT_GT(branches, 40);
  EXPECT_GT(shortcut, 20);  // branches that took a shortcut (the default is bit for bit)
}

TEST(NearestStructure, BrentStopsOnAPlateauAndStillConvergesOnASmoothMinimum) {
  // The one-angle search's Brent ends where f is flat to the last bit (a plateau of the metric:
  // a cylinder grasp whose spin leaves the distance the same over a range of the turn). Before,
  // it halved the plateau by golden sections to its tolerance: 36 poses where 2 tell.
  int evaluations = 0;
  auto plateau = [&](double x) {
    ++evaluations;
    return 1.0 + std::max(0.0, std::abs(x - 0.2) - 0.4);  // flat at 1 over [-0.2, 0.6]
  };
  const double x =
      detail::brentMinimumFrom(plateau, -1.0, 1.0, 0.0, 1.0, 1.4901161193847656e-08, 60);
  EXPECT_EQ(plateau(x), 1.0);
  EXPECT_LE(evaluations, 4);  // (3 plus the line above)
  // A smooth minimum is reached to the tolerance as before: ties there are within rounding.
  for (double at : {0.3, -0.7, 0.95}) {
    auto smooth = [&](double y) { return 2.0 + (y - at) * (y - at) * (1.0 + y * y); };
    const double found =
        detail::brentMinimumFrom(smooth, -1.0, 1.0, 0.0, smooth(0.0), 1.4901161193847656e-08, 60);
    EXPECT_NEAR(found, at, 1e-7) << at;
  }
}

TEST(NearestStructure, NearestRotationIsTheBranchsNearestRotation) {
  // Manifold::nearestRotation, where a type has it: the rotation it sets is at the angle it
  // returns from X's, and no pose of the branch (random ones over the whole branch, and ones
  // about the answer) has a rotation nearer X's. The one-angle search trusts both: it settles a
  // kink there, and tries no certificate where that angle is out of the certificate's reach.
  std::mt19937_64 rng(1207);
  std::normal_distribution<double> normal;
  int branches = 0, radial = 0, separable = 0, near_kinks = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    Params probe = referenceParams(m);
    if (!std::isfinite(m.nearestRotation(p.mobile.pose, &probe))) return;
    ++branches;
    radial += std::string(m.typeName()) == "RadialGrasp";
    separable += m.rotationalDof() >= 0;
    for (int k = 0; k < 6; ++k) {
      Isometry3d X = p.mobile.pose;
      if (k > 0) X.linear() = axisAngle(randomDirection(normal, rng), 0.6 * k) * X.linear();
      if (k == 5) X = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));  // reached
      Params t = referenceParams(m);
      const double angle = m.nearestRotation(X, &t);
      ASSERT_TRUE(std::isfinite(angle)) << p.name;
      EXPECT_NEAR(rotationDistance(m.pose(t).linear(), X.linear()), angle, 1e-9) << p.name;
      near_kinks += angle <= 1e-6;
      double least = std::numeric_limits<double>::infinity();
      for (int s = 0; s < 400; ++s) {
        const Params u =
            s % 2 ? sampleParameters(m, referenceParams(m), 1.0, rng) : nearby(m, t, 1e-3, rng);
        least = std::min(least, rotationDistance(m.pose(u).linear(), X.linear()));
      }
      EXPECT_GE(least, angle - 1e-9) << p.name << " " << m.describe();
    }
  });
  EXPECT_GT(branches, 20);
  EXPECT_GE(radial, 1);  // Somani D's
  EXPECT_GT(separable, 10);
  EXPECT_GT(near_kinks, 10);  // the poses drawn on the branch: X's rotation reached
}

TEST(NearestStructure, OneSearchedAngleIsNoFartherThanADenseScan) {
  // Branches whose only searched parameter is an angle (a cylinder grasp's turn about the axis):
  // the nearest pose is at least as near as the best of 1440 angles across the range, each with
  // its closed-form parameters set, from the initial pose and from poses about the branch.
  std::mt19937_64 rng(184);
  int branches = 0, cases = 0, farther = 0;
  double worst = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    Parameter par[kMaxDof];
    for (int i = 0; i < m.dof(); ++i) par[i] = m.parameter(i);
    int i = -1;
    if (!detail::searchesOneBoundedAngle(m, par, &i)) return;
    ++branches;
    for (int k = 0; k < 4; ++k) {
      Isometry3d X = p.mobile.pose;
      if (k > 0) {
        X = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
        X.translation() += 0.3 * k * Vector3d::UnitX();
        X.linear() = axisAngle(Vector3d(1, 2, 3).normalized(), 0.4 * k) * X.linear();
      }
      const double d = poseDistance(m.pose(nearestParams(m, X)), X);
      const double lo = par[i].periodic ? -kPi : par[i].min;
      const double hi = par[i].periodic ? kPi : par[i].max;
      double scan = std::numeric_limits<double>::infinity();
      for (int s = 0; s <= 1440; ++s) {
        Params t = referenceParams(m);
        t[i] = lo + (hi - lo) * s / 1440;
        scan = std::min(scan, detail::distanceWithTail(m, X, m.closedFormParams(), &t));
      }
      ++cases;
      if (d > scan + 1e-9) {
        ++farther;
        worst = std::max(worst, d - scan);
      }
    }
  });
  EXPECT_GT(branches, 20);
  // Not a proof (nearest_global is false on these branches): a basin narrower than the samples'
  // 30° may hide between them. The search before issue 18's one-angle path missed 4 in 540 here
  // (by up to 0.11), this one 2 (by up to 0.12).
  EXPECT_LE(100 * farther, cases) << "worst by " << worst;
}

TEST(NearestStructure, APoseMovedOffTheBranchComesBackNoFartherThanTheMove) {
  std::mt19937_64 rng(182);
  int branches = 0, certified = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    // Exact branches (charts: AChartComesBackToAPoseMovedOffIt).
    if (m.dof() == 0 || !b.exact) return;
    for (int k = 0; k < 3; ++k) {
      const Isometry3d Y = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
      Isometry3d X = Y;
      const double move = std::pow(10.0, -1.0 - k);  // 10 cm, 1 cm, 1 mm
      std::normal_distribution<double> normal;
      X.translation() += move * randomDirection(normal, rng);
      const Params t = nearestParams(m, X);
      const double d = poseDistance(m.pose(t), X);
      ASSERT_LE(d, move + 1e-9) << p.name << " " << m.describe();
      for (int j = 0; j < 200; ++j) {
        const Params u = sampleParameters(m, t, 0.05, rng);
        ASSERT_GE(poseDistance(m.pose(u), X), d - 1e-9) << p.name << " " << m.describe();
      }
      // Where the answer is a certified kink, settling again finds the same point.
      Params again = t;
      double again_d = d;
      if (settle(m, X, &again, &again_d)) {
        ++certified;
        EXPECT_NEAR(again_d, d, 1e-12) << p.name << " " << m.describe();
      }
      ++branches;
    }
  });
  EXPECT_GT(branches, 300);
  EXPECT_GT(certified, 30);  // the certificate is what ends these searches
}

TEST(NearestStructure, ARotationJustOffTheBranchEndsAtTheNearKinksMinimum) {
  // X's rotation a small ε off a rotation the branch reaches (an initial pose written with 8
  // digits), its position 1 cm off: the distance is a V rounded over ε, and the kink's steps end
  // on the minimum of its model; where the translation pulls the pose off the rotation (a mobile
  // point far from the origin turns onto X's), on the minimum of the distance's convex model. No
  // pose sampled within 1e-6 or 1e-3 of the answer is nearer, but in at most 1 % of the cases:
  // a first-order model can stop on a crease that curves away (a saddle along it). Before these
  // two steps, 33 of the 675 cases here were farther than such a sample (by up to 5.6e-4); after
  // them, 1 (by 2.3e-5).
  std::mt19937_64 rng(185);
  int cases = 0, certified = 0, farther = 0;
  double worst = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    if (m.dof() == 0 || !b.exact || m.rotationalDof() == 0 || allClosedForm(m)) return;
    for (const double eps : {3e-9, 3e-8, 1e-6}) {
      const Isometry3d Y = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
      Isometry3d X = Y;
      std::normal_distribution<double> normal;
      X.translation() += 0.01 * randomDirection(normal, rng);
      X.linear() = axisAngle(randomDirection(normal, rng), eps) * Y.linear();
      const Params t = nearestParams(m, X);
      const double d = poseDistance(m.pose(t), X);
      ASSERT_LE(d, 0.01 + eps + 1e-9) << p.name << " " << m.describe();
      double nearest_sample = d;
      for (int j = 0; j < 400; ++j) {
        const Params u = nearby(m, t, j % 2 == 0 ? 1e-6 : 1e-3, rng);
        nearest_sample = std::min(nearest_sample, poseDistance(m.pose(u), X));
      }
      if (nearest_sample < d - 1e-10) {
        ++farther;
        worst = std::max(worst, d - nearest_sample);
      }
      Params again = t;
      double again_d = d;
      certified += settle(m, X, &again, &again_d);
      ++cases;
    }
  });
  EXPECT_GT(cases, 600);
  EXPECT_LE(100 * farther, cases) << farther << " of " << cases << ", worst by " << worst;
  EXPECT_GT(certified, 30);
}

TEST(NearestStructure, AChartComesBackToAPoseMovedOffIt) {
  // Certified charts (pieces of numeric sets, their tangent coordinates over a box a few
  // thousandths wide): a pose of the chart moved 10 cm, 1 cm or 1 mm. The nearest pose is no
  // farther than the move and no pose sampled over the box is nearer, but in a few cases: the
  // search is local, and where the rotation is reached the distance has a crease a first-order
  // step can stop on. Before the search in the box's own unit (nearest_eval.hpp's searchUnit),
  // 7 of the 2010 cases here had a nearer sample (by up to 5e-5) and 12 were farther than the
  // move (2 by more than 5 %); after it, 2 (by 1.5e-5) and 3.
  std::mt19937_64 rng(186);
  int cases = 0, farther_than_move = 0, sample_nearer = 0;
  double worst = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    if (m.dof() == 0 || b.exact) return;
    for (int k = 0; k < 15; ++k) {
      const Isometry3d Y = m.pose(sampleParameters(m, referenceParams(m), 1.0, rng));
      Isometry3d X = Y;
      const double move = std::pow(10.0, -1.0 - k % 3);  // 10 cm, 1 cm, 1 mm
      std::normal_distribution<double> normal;
      X.translation() += move * randomDirection(normal, rng);
      const Params t = nearestParams(m, X);
      const double d = poseDistance(m.pose(t), X);
      double nearest_sample = d;
      for (int j = 0; j < 200; ++j)
        nearest_sample =
            std::min(nearest_sample, poseDistance(m.pose(sampleParameters(m, t, 1.0, rng)), X));
      ++cases;
      farther_than_move += d > move + 1e-9;
      if (nearest_sample < d - 1e-9) {
        ++sample_nearer;
        worst = std::max(worst, d - nearest_sample);
      }
      ASSERT_LE(d, 1.05 * move) << p.name << " " << m.describe();
    }
  });
  EXPECT_GT(cases, 1500);
  EXPECT_LE(200 * sample_nearer, cases) << sample_nearer << " of " << cases << ", by " << worst;
  EXPECT_LE(200 * farther_than_move, cases) << farther_than_move << " of " << cases;
}

TEST(NearestStructure, NoCertificateAwayFromTheKink) {
  // The rotation of X turned half a radian off every rotation of a 1-DOF spin branch: the
  // rotation distance cannot vanish, there is no kink to certify.
  int tried = 0;
  forEachBranch([&](const Problem& p, const Branch& b) {
    const Manifold& m = *b.manifold;
    if (m.dof() == 0 || m.rotationalDof() != 1 || allClosedForm(m)) return;
    const Isometry3d X = m.pose(referenceParams(m));
    // Turned about a direction no spin axis of the branch can follow (two tries: one is not
    // the spin axis).
    for (const Vector3d axis : {Vector3d::UnitX(), Vector3d::UnitY()}) {
      Isometry3d Z = X;
      Z.linear() = axisAngle(axis, 0.6) * X.linear();
      if (rotationDistance(m.pose(m.project(Z)).linear(), Z.linear()) < 0.1) continue;
      Params best = nearestParams(m, Z);
      double best_d = poseDistance(m.pose(best), Z);
      EXPECT_FALSE(settle(m, Z, &best, &best_d)) << p.name;
      ++tried;
      break;
    }
  });
  EXPECT_GT(tried, 3);
}

TEST(NearestStructure, ACylinderGraspFromAlongTheAxisIsAsNearAsItsBounds) {
  // Somani C with the gripper's approach along the can's axis (either way, any spin about it,
  // anywhere): every pose of the branch has its approach square to the axis, so the rotation
  // distance is π/2 whatever the approach's azimuth, and the distance is flat in the azimuth
  // wherever the translation's is (a plateau: over the arc where the tip reaches the grasp
  // volume, over the whole turn on the axis). The nearest distance is then π/2 plus the least
  // translation, a bound met: the height into [0.05, 0.1], and the distance from the axis into
  // the annulus [0.12 − 0.05, 0.12 + 0.05] that the origin sweeps (the tip 0.12 along the
  // approach, within 0.02–0.05 of the axis).
  ParseResult r =
      parseSpecFile(std::string(RELPOS_DATA_DIR) + "/scenarios/scenario-c-cylinder-grasp.json",
                    builtinRegistry());
  ASSERT_TRUE(r.problem);
  Problem p = *r.problem;
  std::mt19937_64 rng(186);
  std::uniform_real_distribution<double> coordinate(-0.3, 0.3), turn(-kPi, kPi);
  int plateaus = 0;
  for (int k = 0; k < 200; ++k) {
    Isometry3d X = Isometry3d::Identity();
    X.linear() = axisAngle(Vector3d::UnitZ(), turn(rng));
    if (k % 2 == 1) X.linear() = X.linear() * axisAngle(Vector3d::UnitX(), kPi);  // approach −z
    X.translation() = Vector3d(coordinate(rng), coordinate(rng), coordinate(rng));
    if (k < 2) X.translation() = Vector3d(0.0, 0.0, 0.2);   // on the axis: flat over the turn
    if (k == 2) X.translation() = Vector3d(0.1, 0.0, 0.2);  // the scenario's own
    p.mobile.pose = X;
    const Solution s = solve(p, builtinRegistry());
    ASSERT_EQ(s.status, Status::kSolved);
    ASSERT_EQ(s.branches.size(), 1u);
    const Vector3d t = X.translation();
    const double rho = t.head<2>().norm();
    const double dz = std::max({0.0, 0.05 - t.z(), t.z() - 0.1});
    const double dr = std::max({0.0, 0.07 - rho, rho - 0.17});
    plateaus += dr == 0.0;
    const NearestPose n = nearestOnBranch(s.branches[0], X);
    EXPECT_NEAR(n.distance, kPi / 2 + std::hypot(dz, dr), 1e-9) << k << " at " << t.transpose();
  }
  EXPECT_GT(plateaus, 20);
}

}  // namespace
}  // namespace relpos::test
