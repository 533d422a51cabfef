// Grasp and weld spec generator: writes N random specs as JSONL (one spec per line), from a seed.
//   build/bench/relpos_generate_specs N SEED > specs.jsonl
// Kinds, in turn (Somani 004 §VI style, with ranges):
//   cylinder-grasp  a fingertip at a distance range from a random cylinder's axis, a height range
//                   above its base, the approach across the axis (scenario C);
//   cup-grasp       the radial grasp of a cup or can: approach meeting the axis at a right angle,
//                   fingertip distance and height ranges (scenario D);
//   tray-grasp      a palm within three plane-distance ranges of a random tray's faces (E);
//   weld-seam       the torch tip on a random seam line between its start and end, the torch axis
//                   within an angle range of the surface normal (B).
// Every object sits at a random pose; dimensions and ranges are random within plausible bounds.
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "relpos/core/geometry.hpp"

namespace {
using json = nlohmann::ordered_json;
using relpos::Quaterniond;
using relpos::Vector3d;

struct Gen {
  std::mt19937_64 rng;
  double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vector3d unit() {
    Vector3d v;
    do v = Vector3d(u(-1, 1), u(-1, 1), u(-1, 1));
    while (v.norm() < 0.1 || v.norm() > 1);
    return v.normalized();
  }
  json vec(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }
  json pose() {
    const Quaterniond q(Eigen::AngleAxisd(u(-relpos::kPi, relpos::kPi), unit()));
    return {{"position", vec(Vector3d(u(-1, 1), u(-1, 1), u(0, 1)))},
            {"orientation", {q.x(), q.y(), q.z(), q.w()}}};
  }
  json point(const Vector3d& p) { return {{"point", vec(p)}}; }
  json line(const Vector3d& p, const Vector3d& d) {
    return {{"line", {{"point", vec(p)}, {"direction", vec(d)}}}};
  }
  json plane(const Vector3d& p, const Vector3d& n) {
    return {{"plane", {{"point", vec(p)}, {"normal", vec(n)}}}};
  }
  json range(const char* type, const char* fixed, const char* mobile, double lo, double hi) {
    return {{"type", type}, {"fixed", fixed}, {"mobile", mobile}, {"min", lo}, {"max", hi}};
  }
  json gripper(json features) {
    return {{"name", "gripper"}, {"pose", pose()}, {"features", std::move(features)}};
  }

  json cylinderGrasp(int i) {
    const double r = u(0.02, 0.08), h = u(0.08, 0.3);
    json fixed = {{"name", "cylinder"},
                  {"pose", pose()},
                  {"features",
                   {{"body",
                     {{"cylinder",
                       {{"point", vec(Vector3d::Zero())},
                        {"direction", vec(Vector3d::UnitZ())},
                        {"radius", r}}}}},
                    {"base", plane(Vector3d::Zero(), Vector3d::UnitZ())}}}};
    const double tip = u(0.08, 0.15);
    json mobile = gripper({{"tip", point(Vector3d(0, 0, tip))},
                           {"approach", line(Vector3d::Zero(), Vector3d::UnitZ())}});
    const double lo = u(0.0, r), hi = lo + u(0.01, 0.05), z = u(0.2, 0.5) * h;
    return {{"relpos", 1},
            {"name", "cylinder-grasp-" + std::to_string(i)},
            {"fixed", fixed},
            {"mobile", mobile},
            {"constraints",
             {range("distance", "body.axis", "tip", lo, hi),
              range("distance", "base", "tip", z, z + u(0.01, 0.4) * h),
              {{"type", "perpendicular"}, {"fixed", "body.axis"}, {"mobile", "approach"}}}}};
  }

  json cupGrasp(int i) {
    json spec = cylinderGrasp(i);
    spec["name"] = "cup-grasp-" + std::to_string(i);
    spec["fixed"]["name"] = "cup";
    json meets = {{"type", "distance"},
                  {"fixed", "body.axis"},
                  {"mobile", "approach"},
                  {"value", 0},
                  {"parallel", false}};
    spec["constraints"].insert(spec["constraints"].begin(), meets);
    return spec;
  }

  json trayGrasp(int i) {
    const double w = u(0.2, 0.6), d = u(0.15, 0.4);
    json fixed = {{"name", "tray"},
                  {"pose", pose()},
                  {"features",
                   {{"bottom", plane(Vector3d::Zero(), Vector3d::UnitZ())},
                    {"left", plane(Vector3d::Zero(), Vector3d::UnitX())},
                    {"front", plane(Vector3d::Zero(), Vector3d::UnitY())}}}};
    json mobile = gripper({{"palm", plane(Vector3d::Zero(), Vector3d::UnitZ())},
                           {"side", plane(Vector3d::Zero(), Vector3d::UnitX())},
                           {"face", plane(Vector3d::Zero(), Vector3d::UnitY())}});
    const double z = u(0.01, 0.05), x = u(0.05, 0.5) * w, y = u(0.05, 0.5) * d;
    return {{"relpos", 1},
            {"name", "tray-grasp-" + std::to_string(i)},
            {"fixed", fixed},
            {"mobile", mobile},
            {"constraints",
             {range("distance", "bottom", "palm", z, z + u(0.01, 0.08)),
              range("distance", "left", "side", x, x + u(0.05, 0.4) * w),
              range("distance", "front", "face", y, y + u(0.05, 0.4) * d)}}};
  }

  json weldSeam(int i) {
    const double length = u(0.1, 1.0), tilt = u(5, 40);
    json fixed = {{"name", "part"},
                  {"pose", pose()},
                  {"features",
                   {{"seam", line(Vector3d::Zero(), Vector3d::UnitX())},
                    {"start", plane(Vector3d::Zero(), Vector3d::UnitX())},
                    {"surface", plane(Vector3d::Zero(), Vector3d::UnitZ())}}}};
    json mobile = {{"name", "torch"},
                   {"pose", pose()},
                   {"features",
                    {{"tip", point(Vector3d(0, 0, u(0.1, 0.3)))},
                     {"axis", line(Vector3d::Zero(), Vector3d::UnitZ())}}}};
    return {{"relpos", 1},
            {"name", "weld-seam-" + std::to_string(i)},
            {"units", {{"angle", "deg"}}},
            {"fixed", fixed},
            {"mobile", mobile},
            {"constraints",
             {{{"type", "coincident"}, {"fixed", "seam"}, {"mobile", "tip"}},
              range("distance", "start", "tip", 0.0, length),
              range("angle", "surface", "axis", 90 - tilt, 90)}}};
  }
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: relpos_generate_specs N SEED > specs.jsonl\n");
    return 2;
  }
  const long n = std::strtol(argv[1], nullptr, 10);
  Gen g{std::mt19937_64(std::strtoull(argv[2], nullptr, 10))};
  for (long i = 0; i < n; ++i) {
    const int k = static_cast<int>(i);
    const json spec = i % 4 == 0   ? g.cylinderGrasp(k)
                      : i % 4 == 1 ? g.cupGrasp(k)
                      : i % 4 == 2 ? g.trayGrasp(k)
                                   : g.weldSeam(k);
    std::puts(spec.dump().c_str());
  }
  return 0;
}
