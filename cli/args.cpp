// The command line's options (cli.hpp Args), shared by every command.
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>

#include "cli.hpp"

namespace relpos::cli {

namespace {

double parseNonNegative(const std::string& flag, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end || !(x >= 0) || !std::isfinite(x))
    throw UsageError(flag + ": expected a non-negative number, got '" + v + "'");
  return x;
}

long parseInt(const std::string& flag, const std::string& v, long lo, long hi) {
  char* end = nullptr;
  long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end || x < lo || x > hi)
    throw UsageError(flag + ": expected an integer in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got '" + v + "'");
  return x;
}

}  // namespace

Args parseArgs(int argc, char** argv, int first) {
  Args a;
  for (int i = first; i < argc; ++i) {
    std::string s = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(s + ": missing value");
      return argv[++i];
    };
    if (s == "--samples")
      a.result.samples = static_cast<int>(parseInt(s, value(), 0, 1000000)),
      a.samples_given = true;
    else if (s == "--seed")
      a.result.seed = static_cast<std::uint64_t>(parseInt(s, value(), 0, LONG_MAX));
    else if (s == "--repeat")
      a.repeat = static_cast<int>(parseInt(s, value(), 1, 1000000));
    else if (s == "--window")
      a.result.window = parseNonNegative(s, value()), a.window_given = true;
    else if (s == "--format")
      a.format = value();
    else if (s == "--angles") {
      const std::string unit = value();
      if (unit != "deg" && unit != "rad")
        throw UsageError("--angles: expected deg or rad, got '" + unit + "'");
      a.degrees = unit == "deg";
    } else if (s == "--collision")
      a.collision = true;
    else if (s == "--clearance")
      a.result.clearance = parseNonNegative(s, value()), a.collision_option = true;
    else if (s == "--collision-samples")
      a.result.collision_samples = static_cast<int>(parseInt(s, value(), 0, 1000000)),
      a.collision_option = true;
    else if (s == "-o")
      a.out = value(), a.out_given = true;
    else if (s == "--coverage")
      a.coverage = true;
    else if (s == "--plugin")
      a.plugins.push_back(value());
    else if (s == "--jobs")
      a.jobs = static_cast<int>(parseInt(s, value(), 1, 1024));
    else if (s == "--allow-override")
      a.allow_override = true;
    else if (s.size() > 1 && s[0] == '-')
      throw UsageError("unknown option '" + s + "'");
    else
      a.positional.push_back(s);
  }
  return a;
}

void requireCollisionForItsOptions(const Args& a) {
  if (a.collision_option && !a.collision)
    throw UsageError("--clearance and --collision-samples need --collision");
}

}  // namespace relpos::cli
