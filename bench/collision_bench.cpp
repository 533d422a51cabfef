// A collision-filtered solve as `relpos solve --collision` runs it, minus file reading: solve the
// part-on-a-table-beside-a-wall problem, take the branch's nearest pose, and filter the branch
// with 64 samples against meshes of about 10k triangles each (mobile, table, wall: finely
// tessellated boxes). Meshes are built once (a control loop or batch keeps its scene).
//   build/bench/relpos_collision_bench --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "relpos/builtins/builtins.hpp"
#include "relpos/collision/branch_filter.hpp"

namespace {
using relpos::Vector3d;
using relpos::collision::Mesh;

// The part (20 x 10 x 6 cm, bottom face at its frame's z = 0) resting on a table beside a wall:
// the part an n x n-gridded box (12 n² triangles), table and wall m x m-gridded.
relpos::collision::Scene partOnTableScene(int n, int m) {
  using namespace relpos;
  Isometry3d table = Isometry3d::Identity(), wall = Isometry3d::Identity();
  table.translation() = Vector3d(0, 0, -0.02);
  wall.translation() = Vector3d(0.5, 0, 0.15);
  Mesh part = collision::boxMesh(Vector3d(0.1, 0.05, 0.03), n);
  for (auto& v : part.vertices) v.z() += 0.03;
  return collision::Scene(
      collision::buildModel(part),
      {{"table", table, collision::buildModel(collision::boxMesh(Vector3d(0.6, 0.4, 0.02), m))},
       {"wall", wall, collision::buildModel(collision::boxMesh(Vector3d(0.02, 0.4, 0.15), m))}});
}

void BM_CollisionFilteredSolve(benchmark::State& state) {
  using namespace relpos;
  Problem p;
  p.addFixedFeature("top", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("lane", Feature::makeLine({0, 0, 0}, {1, 0, 0}))
      .addMobileFeature("bottom", Feature::makePlane({0, 0, 0}, {0, 0, -1}))
      .addMobileFeature("centre", Feature::makePoint({0, 0, 0}))
      .addMobileFeature("long", Feature::makeLine({0, 0, 0}, {1, 0, 0}));
  p.addConstraint("coincident", "top", "bottom", 0.0, Orientation::kOpposed)
      .addConstraint("coincident", "lane", "centre")
      .addConstraint("parallel", "lane", "long");
  p.mobile.pose.translation() = Vector3d(0.45, 0.02, 0.05);
  const int n = static_cast<int>(state.range(0));
  const collision::Scene scene = partOnTableScene(n, static_cast<int>(state.range(1)));
  Workspace ws;
  Solution s;
  collision::FilterOptions opt;
  opt.samples = 64;
  for (auto _ : state) {
    solve(p, builtinRegistry(), SolverOptions(), ws, s);
    const NearestPose near = nearestOnBranch(s.branches[0], p.mobile.pose);
    const auto c = collision::filterBranch(scene, s.branches[0], near, p.mobile.pose, opt);
    benchmark::DoNotOptimize(c.blocked_samples);
  }
  state.counters["part_triangles"] = 12.0 * n * n;
}
// Args: part grid, table/wall grid. 29: ~10k triangles; 1: a plain 12-triangle box.
BENCHMARK(BM_CollisionFilteredSolve)
    ->Args({29, 29})
    ->Args({29, 1})
    ->Args({10, 10})
    ->Unit(benchmark::kMicrosecond);

// The same branch, only the 64 sample verdicts (no nearest-free search): the cost per pose of a
// part resting on a table (every pose touches it) beside a wall.
void BM_SixtyFourRestingSamples(benchmark::State& state) {
  using namespace relpos;
  const collision::Scene scene =
      partOnTableScene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) {
    int blocked = 0;
    for (int k = 0; k < 64; ++k) {
      Isometry3d X = Isometry3d::Identity();
      X.translation().x() = -0.5 + 1.5 * k / 63.0;
      blocked += scene.collides(X, 0.0);
    }
    benchmark::DoNotOptimize(blocked);
  }
}
BENCHMARK(BM_SixtyFourRestingSamples)->Args({29, 29})->Args({29, 1})->Unit(benchmark::kMicrosecond);

// A closed cylinder of radius r and height z1 − z0 about the z axis: `sides` around, `rings`
// along, fan-capped (2·sides·rings + 2·sides triangles), wound outward.
Mesh cylinderMesh(double r, double z0, double z1, int sides, int rings) {
  Mesh m;
  for (int k = 0; k <= rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * relpos::kPi * i / sides;
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z0 + (z1 - z0) * k / rings);
    }
  const int bottom = static_cast<int>(m.vertices.size()), top = bottom + 1;
  m.vertices.emplace_back(0, 0, z0);
  m.vertices.emplace_back(0, 0, z1);
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const int a = k * sides + i, b = k * sides + (i + 1) % sides;
      m.triangles.push_back({a, b, b + sides});
      m.triangles.push_back({a, b + sides, a + sides});
    }
  for (int i = 0; i < sides; ++i) {
    m.triangles.push_back({bottom, (i + 1) % sides, i});
    m.triangles.push_back({top, rings * sides + i, rings * sides + (i + 1) % sides});
  }
  relpos::collision::classify(m);
  return m;
}

Mesh merged(std::initializer_list<Mesh> parts) {
  Mesh m;
  for (const Mesh& p : parts) {
    const int base = static_cast<int>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), p.vertices.begin(), p.vertices.end());
    for (const auto& t : p.triangles)
      m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  relpos::collision::classify(m);
  return m;
}

Mesh moved(Mesh m, const Vector3d& by) {
  for (auto& v : m.vertices) v += by;
  return m;
}

// Somani's soda-can grasp (scenario D) with ~10k-triangle meshes: the can (10.2k), the gripper
// (palm and two fingers, 9.8k), the counter under the can (10.1k). Both branches filtered with 64
// samples each, as `relpos solve --collision` does, including the nearest-free search.
void BM_GraspCollisionFilteredSolve(benchmark::State& state) {
  using namespace relpos;
  Problem p;
  p.fixed.pose.translation() = Vector3d(0.4, 0.1, 0.0);
  p.addFixedFeature("axis", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addFixedFeature("bottom", Feature::makePlane({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("approach", Feature::makeLine({0, 0, 0}, {0, 0, 1}))
      .addMobileFeature("tip", Feature::makePoint({0, 0, 0.12}));
  p.addConstraint("distance", "axis", "approach", 0.0)
      .addConstraint("perpendicular", "axis", "approach");
  p.constraints[0].parallel = false;
  p.addConstraint("distance", "axis", "tip").addConstraint("distance", "bottom", "tip");
  p.constraints[2].has_value = p.constraints[3].has_value = false;
  p.constraints[2].min = 0.02, p.constraints[2].max = 0.05;
  p.constraints[3].min = 0.05, p.constraints[3].max = 0.1;
  p.mobile.pose.translation() = Vector3d(0.3, 0.1, 0.06);
  p.mobile.pose.linear() = axisAngle(Vector3d::UnitY(), kPi / 2);
  Isometry3d counter = Isometry3d::Identity();
  counter.translation() = Vector3d(0.4, 0.1, -0.02);
  const Mesh gripper =
      merged({moved(collision::boxMesh(Vector3d(0.06, 0.06, 0.03), 20), {0, 0, 0.03}),
              moved(collision::boxMesh(Vector3d(0.01, 0.005, 0.04), 14), {0, 0.05, 0.1}),
              moved(collision::boxMesh(Vector3d(0.01, 0.005, 0.04), 14), {0, -0.05, 0.1})});
  const collision::Scene scene(
      collision::buildModel(gripper),
      {{"can", p.fixed.pose, collision::buildModel(cylinderMesh(0.033, 0.0, 0.12, 100, 50))},
       {"counter", counter,
        collision::buildModel(collision::boxMesh(Vector3d(0.3, 0.3, 0.02), 29))}});
  Workspace ws;
  Solution s;
  collision::FilterOptions opt;
  opt.samples = 64;
  int free_samples = 0;
  for (auto _ : state) {
    solve(p, builtinRegistry(), SolverOptions(), ws, s);
    free_samples = 0;
    for (const Branch& b : s.branches) {
      const NearestPose near = nearestOnBranch(b, p.mobile.pose);
      const auto c = collision::filterBranch(scene, b, near, p.mobile.pose, opt);
      free_samples += static_cast<int>(c.free_samples.size());
    }
    benchmark::DoNotOptimize(free_samples);
  }
  state.counters["branches"] = static_cast<double>(s.branches.size());
  state.counters["free_samples"] = free_samples;
  state.counters["gripper_triangles"] = static_cast<double>(gripper.triangles.size());
}
BENCHMARK(BM_GraspCollisionFilteredSolve)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
