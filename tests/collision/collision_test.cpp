// Collision filtering against an exact oracle (box_oracle.hpp): what relpos reports free never
// collides, what it reports colliding does (beyond the touching tolerance), resting contact is
// free, clearance works, a solid inside a solid is seen; nearest_free is free, on the branch and
// no farther than needed; bad meshes are refused with their JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "box_oracle.hpp"
#include "evaluator.hpp"
#include "random_problems.hpp"
#include "relpos/collision/branch_filter.hpp"
#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {
using collision::boxMesh;
using collision::buildModel;
using collision::Scene;
using collision::SceneObject;

Scene boxScene(const Vector3d& mobile_h, const Box& obstacle) {
  return Scene(buildModel(boxMesh(mobile_h)),
               {SceneObject{"obstacle", obstacle.X, buildModel(boxMesh(obstacle.h))}});
}

// A box of 5 cm to 0.5 m half-extents at a random pose (axis-aligned: exactly parallel edges).
Box randomBox(Rng& rng, bool axis_aligned) {
  const Isometry3d X = rng.pose(axis_aligned);
  return Box{X, Vector3d(rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5), rng.uniform(0.05, 0.5))};
}

// Random box pairs, many overlapping a little, many apart a little, some touching exactly.
TEST(CollisionOracle, BoxesAgreeWithTheSeparatingAxisTest) {
  Rng rng(61);
  int collide = 0, free = 0, touching = 0;
  for (int k = 0; k < 600; ++k) {
    const Box a = randomBox(rng, k % 3 == 0);
    Box b = randomBox(rng, k % 3 == 0);
    // b's centre a random distance from a's along a random direction.
    b.X.translation() = a.X.translation() + rng.unit() * rng.uniform(0.0, 1.2);
    const Scene scene = boxScene(b.h, a);
    const double depth = boxPenetration(a, b);
    SCOPED_TRACE("pair #" + std::to_string(k) + " oracle depth " + std::to_string(depth));
    const bool reported = scene.collides(b.X, 0.0);
    if (depth > collision::kTouchTolerance + 1e-9) {
      EXPECT_TRUE(reported) << "reported free, the oracle finds them interpenetrating";
      ++collide;
    } else if (depth < -1e-9) {
      EXPECT_FALSE(reported) << "reported colliding, the oracle finds them apart";
      ++free;
    }
  }
  // Resting contact: b on top of an axis-aligned a, face to face, shifted sideways.
  for (int k = 0; k < 100; ++k, ++touching) {
    const Box a{Isometry3d::Identity(), Vector3d(0.6, 0.4, 0.02)};
    Box b{Isometry3d::Identity(), Vector3d(rng.uniform(0.02, 0.2), rng.uniform(0.02, 0.2), 0.03)};
    b.X.linear() = axisAngle(Vector3d::UnitZ(), rng.uniform(-kPi, kPi));
    b.X.translation() = Vector3d(rng.uniform(-0.5, 0.5), rng.uniform(-0.3, 0.3), 0.02 + 0.03);
    EXPECT_FALSE(boxScene(b.h, a).collides(b.X, 0.0)) << "resting contact #" << k;
    // Pressed in by 1e-4: colliding.
    b.X.translation().z() -= 1e-4;
    EXPECT_TRUE(boxScene(b.h, a).collides(b.X, 0.0)) << "pressed in #" << k;
  }
  EXPECT_GT(collide, 100);
  EXPECT_GT(free, 100);
}

// Oracle depths near touching and near the touching tolerance, either side: where a shortcut
// that is almost right would show.
constexpr double kNearTouching[] = {-1e-3, -1e-5, -1e-7, 1e-7, 0.97e-6, 1.03e-6, 1e-5, 1e-3, 0.05};

// Moves b from a's centre along `dir` to where the oracle's depth is `target` (bisection).
void placeAtDepth(const Box& a, Box* b, const Vector3d& dir, double target) {
  double in = 0.0, out = 4.0 * (a.h.norm() + b->h.norm());
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (in + out);
    b->X.translation() = a.X.translation() + mid * dir;
    (boxPenetration(a, *b) > target ? in : out) = mid;
  }
  b->X.translation() = a.X.translation() + in * dir;
}

// The same pairs with finely tessellated boxes (the hull path must see through the grid points),
// and the reported depth is the oracle's penetration depth (exact for two convex solids).
TEST(CollisionOracle, TessellatedBoxesAgreeAndReportTheExactDepth) {
  Rng rng(63);
  int collide = 0, free = 0, near_tolerance = 0;
  for (int k = 0; k < 300; ++k) {
    const Box a = randomBox(rng, k % 3 == 0);
    Box b = randomBox(rng, k % 3 == 0);
    placeAtDepth(a, &b, rng.unit(), kNearTouching[k % std::size(kNearTouching)]);
    const Scene scene(buildModel(boxMesh(b.h, 1 + k % 7)),
                      {SceneObject{"obstacle", a.X, buildModel(boxMesh(a.h, 1 + k % 5))}});
    const double depth = boxPenetration(a, b);
    SCOPED_TRACE("pair #" + std::to_string(k) + " oracle depth " + std::to_string(depth));
    std::vector<collision::Contact> contacts;
    const bool reported = scene.collides(b.X, 0.0);
    EXPECT_EQ(scene.collides(b.X, 0.0, &contacts), reported) << "verdict depends on the contacts";
    // Two convex solids: the verdict is exact up to rounding, touching tolerance included.
    if (depth > collision::kTouchTolerance + 1e-9) {
      EXPECT_TRUE(reported) << "reported free, the oracle finds them interpenetrating";
      ASSERT_EQ(contacts.size(), 1u);
      EXPECT_NEAR(contacts[0].depth, depth, 1e-9 * (1 + depth));
      ++collide;
    } else if (depth < collision::kTouchTolerance - 1e-9) {
      EXPECT_FALSE(reported) << "reported colliding, the oracle finds them touching or apart";
      ++free;
    }
    near_tolerance += std::abs(depth - collision::kTouchTolerance) < 2e-7;
  }
  EXPECT_GT(collide, 100);
  EXPECT_GT(free, 100);
  EXPECT_GT(near_tolerance, 50);
}

// A closed prism over a polygon star-shaped from its first vertex (fan-triangulated caps), wound
// outward for a counter-clockwise polygon.
collision::Mesh prismMesh(const std::vector<Eigen::Vector2d>& polygon, double z0, double z1) {
  collision::Mesh m;
  const int n = static_cast<int>(polygon.size());
  for (double z : {z0, z1})
    for (const auto& p : polygon) m.vertices.emplace_back(p.x(), p.y(), z);
  for (int i = 1; i + 1 < n; ++i) {
    m.triangles.push_back({0, i + 1, i});          // bottom, facing −z
    m.triangles.push_back({n, n + i, n + i + 1});  // top, facing +z
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});
    m.triangles.push_back({i, n + j, n + i});
  }
  collision::classify(m);
  return m;
}

collision::Mesh twoBoxes(const Box& p, const Box& q) {
  collision::Mesh m = boxMesh(p.h, 2), second = boxMesh(q.h, 3);
  for (auto& v : m.vertices) v = p.X * v;
  const int base = static_cast<int>(m.vertices.size());
  for (const auto& v : second.vertices) m.vertices.push_back(q.X * v);
  for (const auto& t : second.triangles)
    m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  collision::classify(m);
  return m;
}

// Meshes that are not one convex solid, against the oracle on their parts: an L-shaped prism
// (non-convex: its hull proves poses free, FCL decides the rest) and a mesh of two separate boxes
// (two pieces). Each is the union of two boxes B1, B2: it collides when either does (beyond
// touching) and is free when both are apart.
TEST(CollisionOracle, NonConvexAndTwoPieceMeshesAgreeWithTheirParts) {
  // The L: [0, 0.2] x [0, 0.1] plus [0, 0.1] x [0.1, 0.2], 0.06 high.
  const Box b1{Isometry3d(Eigen::Translation3d(0.1, 0.05, 0.03)), Vector3d(0.1, 0.05, 0.03)};
  const Box b2{Isometry3d(Eigen::Translation3d(0.05, 0.15, 0.03)), Vector3d(0.05, 0.05, 0.03)};
  const collision::Mesh ell =
      prismMesh({{0, 0}, {0.2, 0}, {0.2, 0.1}, {0.1, 0.1}, {0.1, 0.2}, {0, 0.2}}, 0.0, 0.06);
  ASSERT_TRUE(ell.closed && ell.oriented);
  // Two boxes apart: the L's parts pulled 5 cm apart along y.
  Box far2 = b2;
  far2.X.translation().y() += 0.05;
  const collision::Mesh pair = twoBoxes(b1, far2);
  Rng rng(64);
  for (const bool l_shape : {true, false}) {
    const Box parts[2] = {b1, l_shape ? b2 : far2};
    int collide = 0, free = 0;
    for (int k = 0; k < 300; ++k) {
      const Box obstacle{
          rng.pose(k % 3 == 0),
          Vector3d(rng.uniform(0.02, 0.15), rng.uniform(0.02, 0.15), rng.uniform(0.02, 0.15))};
      Isometry3d X = rng.pose(k % 4 == 0);
      X.translation() = obstacle.X.translation() + rng.unit() * rng.uniform(0.0, 0.3);
      const Scene scene(buildModel(l_shape ? ell : pair),
                        {SceneObject{"obstacle", obstacle.X, buildModel(boxMesh(obstacle.h, 2))}});
      double deepest = -std::numeric_limits<double>::infinity();
      for (const Box& part : parts)
        deepest = std::max(deepest, boxPenetration(obstacle, Box{X * part.X, part.h}));
      SCOPED_TRACE(std::string(l_shape ? "L" : "two boxes") + " #" + std::to_string(k) +
                   " deepest part " + std::to_string(deepest));
      const bool reported = scene.collides(X, 0.0);
      if (deepest > collision::kTouchTolerance + 1e-9) {
        EXPECT_TRUE(reported) << "reported free, a part interpenetrates";
        ++collide;
      } else if (deepest < -1e-9) {
        EXPECT_FALSE(reported) << "reported colliding, both parts are apart";
        ++free;
      }
    }
    EXPECT_GT(collide, 50);
    EXPECT_GT(free, 50);
  }
}

// A hollow box (an outer shell and an inner one wound inward, one mesh): its cavity is not part
// of the solid. A box in the cavity is free, one across the inner wall or inside the wall's
// material collides — whichever of the two is the mobile object.
TEST(CollisionOracle, AHollowSolidsCavityIsFree) {
  collision::Mesh hollow = boxMesh(Vector3d(0.3, 0.3, 0.3), 2);
  collision::Mesh inner = boxMesh(Vector3d(0.2, 0.2, 0.2), 3);
  const int base = static_cast<int>(hollow.vertices.size());
  hollow.vertices.insert(hollow.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (const auto& t : inner.triangles)  // reversed: the inner shell faces the cavity
    hollow.triangles.push_back({t[0] + base, t[2] + base, t[1] + base});
  collision::classify(hollow);
  ASSERT_TRUE(hollow.closed && hollow.oriented);
  const struct {
    double x, h;
    bool collides;
    const char* what;
  } cases[] = {{0.0, 0.05, false, "in the cavity"},
               {0.12, 0.05, false, "in the cavity, near the wall"},
               {0.2, 0.05, true, "across the inner wall"},
               {0.25, 0.02, true, "inside the wall's material"},
               {0.3, 0.05, true, "across the outer wall"},
               {0.5, 0.05, false, "outside"}};
  for (const auto& c : cases) {
    Isometry3d X = Isometry3d::Identity();
    X.translation().x() = c.x;
    const Scene small_moves(buildModel(boxMesh(Vector3d(c.h, c.h, c.h), 2)),
                            {SceneObject{"hollow", Isometry3d::Identity(), buildModel(hollow)}});
    EXPECT_EQ(small_moves.collides(X, 0.0), c.collides) << "small box mobile, " << c.what;
    const Scene hollow_moves(
        buildModel(hollow),
        {SceneObject{"small", X, buildModel(boxMesh(Vector3d(c.h, c.h, c.h), 2))}});
    EXPECT_EQ(hollow_moves.collides(Isometry3d::Identity(), 0.0), c.collides)
        << "hollow box mobile, " << c.what;
  }
}

TEST(CollisionOracle, SpheresAgreeBeyondTheirTessellation) {
  Rng rng(62);
  const double r = 0.2;
  const int levels = 3;  // 1280 triangles
  // The inscribed polyhedron lies between r cos(θ) and r from the centre; θ bounds the angle
  // between a face's centre and its vertices (< the edge angle of level 3, generously).
  const double sagitta = r * (1 - std::cos(0.2));
  const Scene scene(buildModel(collision::sphereMesh(r, levels)), [] {
    return std::vector<SceneObject>{
        {"box", Isometry3d::Identity(), buildModel(boxMesh(Vector3d(0.3, 0.2, 0.1)))}};
  }());
  const Box box{Isometry3d::Identity(), Vector3d(0.3, 0.2, 0.1)};
  int checked_collide = 0, checked_free = 0;
  for (int k = 0; k < 400; ++k) {
    Isometry3d X = rng.pose();
    X.translation() =
        Vector3d(rng.uniform(-0.6, 0.6), rng.uniform(-0.5, 0.5), rng.uniform(-0.4, 0.4));
    const double d = sphereBoxDistance(X.translation(), r, box);
    const bool reported = scene.collides(X, 0.0);
    if (d > 1e-9) {
      EXPECT_FALSE(reported) << "sphere apart by " << d << " reported colliding";
      ++checked_free;
    } else if (-d > sagitta + collision::kTouchTolerance) {
      EXPECT_TRUE(reported) << "sphere in by " << -d << " reported free";
      ++checked_collide;
    }
  }
  EXPECT_GT(checked_collide, 50);
  EXPECT_GT(checked_free, 50);
}

TEST(CollisionOracle, ASolidInsideASolidCollides) {
  const Box big{Isometry3d::Identity(), Vector3d(0.5, 0.5, 0.5)};
  Isometry3d X = Isometry3d::Identity();
  X.linear() = axisAngle(Vector3d(1, 2, 3).normalized(), 0.4);
  EXPECT_TRUE(boxScene(Vector3d(0.1, 0.1, 0.1), big).collides(X, 0.0)) << "small inside big";
  // The big one around the small one: the same, seen from the other side.
  const Box small{Isometry3d::Identity(), Vector3d(0.1, 0.1, 0.1)};
  EXPECT_TRUE(boxScene(Vector3d(0.5, 0.5, 0.5), small).collides(X, 0.0)) << "big around small";
  // Inside, resting on the inside of the floor: touching the surface, but within the solid.
  Isometry3d Y = Isometry3d::Identity();
  Y.translation() = Vector3d(0.1, -0.2, -0.5 + 0.1);
  EXPECT_TRUE(boxScene(Vector3d(0.1, 0.1, 0.1), big).collides(Y, 0.0));
}

TEST(CollisionOracle, ClearanceDemandsTheGap) {
  const Box table{Isometry3d::Identity(), Vector3d(0.6, 0.4, 0.02)};
  for (double gap : {0.0, 0.004, 0.02}) {
    Isometry3d X = Isometry3d::Identity();
    X.translation() = Vector3d(0.1, 0.0, 0.02 + 0.03 + gap);
    const Scene scene = boxScene(Vector3d(0.1, 0.05, 0.03), table);
    for (double clearance : {0.0, 0.01}) {
      std::vector<collision::Contact> contacts;
      const bool reported = scene.collides(X, clearance, &contacts);
      SCOPED_TRACE("gap " + std::to_string(gap) + " clearance " + std::to_string(clearance));
      EXPECT_EQ(reported, gap < clearance);
      if (reported) {
        ASSERT_EQ(contacts.size(), 1u);
        EXPECT_EQ(contacts[0].object, "obstacle");
        EXPECT_NEAR(contacts[0].depth, gap - clearance, 1e-9);
      }
    }
  }
}

// --- the bundled examples, through the branch filter --------------------------------------------

struct Loaded {
  Problem problem;
  Solution solution;
  std::unique_ptr<Scene> scene;
};

Loaded load(const std::string& name) {
  Loaded l;
  const std::string file = RELPOS_DATA_DIR "/collision/" + name + ".json";
  ParseResult r = parseSpecFile(file, builtinRegistry());
  EXPECT_TRUE(r.problem);
  l.problem = *r.problem;
  l.solution = solve(l.problem, builtinRegistry());
  collision::MeshCache cache;
  std::vector<Diagnostic> errors, warnings;
  l.scene =
      collision::buildScene(l.problem, RELPOS_DATA_DIR "/collision", cache, &errors, &warnings);
  EXPECT_TRUE(errors.empty()) << errors.front().message;
  EXPECT_TRUE(warnings.empty());
  return l;
}

TEST(CollisionFilter, PartSlidesToTheWallAndStopsThere) {
  Loaded l = load("part-on-table-beside-wall");
  ASSERT_EQ(l.solution.status, Status::kSolved);
  ASSERT_EQ(l.solution.branches.size(), 1u);
  const Branch& br = l.solution.branches[0];
  const NearestPose n = nearestOnBranch(br, l.problem.mobile.pose);
  collision::FilterOptions opt;
  const auto c = collision::filterBranch(*l.scene, br, n, l.problem.mobile.pose, opt);
  // The oracle: the part (20 x 10 x 6 cm, bottom on the table) against the wall (x in
  // [0.48, 0.52]) and the table (resting: touching).
  const Box wall{Isometry3d(Eigen::Translation3d(0.5, 0, 0.15)), Vector3d(0.02, 0.4, 0.15)};
  auto partBox = [](const Isometry3d& X) {
    return Box{X * Eigen::Translation3d(0, 0, 0.03), Vector3d(0.1, 0.05, 0.03)};
  };
  EXPECT_TRUE(c.nearest_collides);  // at x = 0.45 it is in the wall
  ASSERT_TRUE(c.has_nearest_free);
  const Isometry3d& F = c.nearest_free.pose;
  EXPECT_LE(boxPenetration(wall, partBox(F)), collision::kTouchTolerance);
  EXPECT_LT(worstViolation(l.problem, F), 1e-9);
  // No farther than needed: the free stretch nearest x = 0.45 starts at x = 0.48 − 0.1.
  EXPECT_NEAR(F.translation().x(), 0.38, 1e-6);
  Isometry3d best = n.pose;
  best.translation().x() = 0.38;
  EXPECT_LE(c.nearest_free.distance, poseDistance(best, l.problem.mobile.pose) + 1e-6);
  // Free and blocked stretches; every free sample is free for the oracle, every blocked one not.
  EXPECT_GT(c.free_samples.size(), 0u);
  EXPECT_GT(c.blocked_samples, 0);
  for (const auto& f : c.free_samples) {
    EXPECT_LE(boxPenetration(wall, partBox(f.pose)), collision::kTouchTolerance);
    EXPECT_LT(worstViolation(l.problem, f.pose), 1e-9);
  }
}

TEST(CollisionFilter, OneOfTwoDiscreteSolutionsCollides) {
  Loaded l = load("arm-either-side");
  ASSERT_EQ(l.solution.branches.size(), 2u);
  const Box block{Isometry3d(Eigen::Translation3d(-0.35, 0, 0.5)), Vector3d(0.2, 0.1, 0.1)};
  int free_branches = 0;
  for (const Branch& br : l.solution.branches) {
    ASSERT_EQ(br.manifold->dof(), 0);
    const NearestPose n = nearestOnBranch(br, l.problem.mobile.pose);
    const auto c = collision::filterBranch(*l.scene, br, n, l.problem.mobile.pose, {});
    const Box arm{n.pose * Eigen::Translation3d(0.2, 0, 0), Vector3d(0.2, 0.02, 0.02)};
    const bool oracle = boxPenetration(block, arm) > collision::kTouchTolerance;
    EXPECT_EQ(c.nearest_collides, oracle);
    EXPECT_EQ(c.has_nearest_free, !oracle);
    EXPECT_EQ(c.free_samples.size() + c.blocked_samples, 1u);
    if (oracle) {
      EXPECT_EQ(c.nearest_free_reason, "the branch's only pose collides");
    }
    free_branches += !oracle;
  }
  EXPECT_EQ(free_branches, 1);
}

TEST(CollisionFilter, GraspSamplesAreSplitAndDeterministic) {
  Loaded l = load("soda-can-grasp-collision");
  ASSERT_EQ(l.solution.status, Status::kSolved);
  for (const Branch& br : l.solution.branches) {
    const NearestPose n = nearestOnBranch(br, l.problem.mobile.pose);
    collision::FilterOptions opt;
    opt.seed = 3;
    const auto c = collision::filterBranch(*l.scene, br, n, l.problem.mobile.pose, opt);
    const auto again = collision::filterBranch(*l.scene, br, n, l.problem.mobile.pose, opt);
    EXPECT_EQ(c.free_samples.size() + c.blocked_samples, 64u);
    EXPECT_GT(c.free_samples.size(), 0u);
    EXPECT_GT(c.blocked_samples, 0);  // the counter is in the way of low grasps
    ASSERT_EQ(c.free_samples.size(), again.free_samples.size());
    for (std::size_t i = 0; i < c.free_samples.size(); ++i) {
      EXPECT_EQ(c.free_samples[i].parameters, again.free_samples[i].parameters);
      EXPECT_LT(worstViolation(l.problem, c.free_samples[i].pose), 1e-9);
    }
  }
}

}  // namespace
}  // namespace relpos::test
