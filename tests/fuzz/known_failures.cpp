#include "known_failures.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

namespace relpos::fuzz {
namespace {

bool strict() {
  static const bool s = [] {
    const char* v = std::getenv("RELPOS_FUZZ_STRICT");
    return v && *v && std::strcmp(v, "0") != 0;
  }();
  return s;
}

bool contains(std::string_view s, std::string_view part) {
  return s.find(part) != std::string_view::npos;
}

const KnownFailure kInfiniteNearestDistance = {
    "infinite-nearest-distance",
    "an initial mobile pose beyond ~1e154 (e.g. position [-1e300, 0, 0]) overflows the squared "
    "norm in poseDistance (core/src/manifold.cpp, Eigen norm()): the nearest distance is infinite, "
    "written null, and `best` is null although there are branches (issue 13: 'scale before "
    "squaring'; the size check that makes huge problems unhandled does not look at the initial "
    "pose)"};

const KnownFailure kFarFrameAngleFloor = {
    "far-frame-angle-floor",
    "a problem placed 3e13 or more from the origin (e.g. a fixed frame at [0, 0, 1e15] holding "
    "planes with normals z and y, a mobile plane at distances from both) is 'solved' although "
    "it is infeasible: the angle tolerance's rounding floor over the problem's size (main "
    "5449afe) grows past pi/2, so perpendicular planes pass for parallel; the poses break the "
    "constraints by ~1 rad. In doubt the answer should be unhandled (issue 13, deliverable 5)"};

// The problem's size a wrong-answer finding measures by ("relative to the problem's size X").
double sizeIn(std::string_view detail) {
  constexpr std::string_view at = "the problem's size ";
  const std::size_t i = detail.find(at);
  if (i == std::string_view::npos) return 0;
  return std::strtod(std::string(detail.substr(i + at.size())).c_str(), nullptr);
}

// Whether the text spells a finite number of magnitude 1e150 or more (digits, sign, point and
// exponent in a row, as JSON writes numbers).
bool holdsHugeNumber(std::string_view text) {
  auto numeric = [](char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
  };
  for (std::size_t i = 0; i < text.size();) {
    if (!numeric(text[i]) || text[i] == 'e' || text[i] == 'E') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && numeric(text[j])) ++j;
    const std::string literal(text.substr(i, j - i));
    const double v = std::strtod(literal.c_str(), nullptr);
    if (std::isfinite(v) && std::abs(v) >= 1e150) return true;
    i = j;
  }
  return false;
}

}  // namespace

const KnownFailure* knownFailure(const Finding& f, std::string_view input) {
  if (strict()) return nullptr;
  // Only the two fields the overflow breaks: a huge number anywhere else is no excuse.
  if (f.kind == "bad-output" && holdsHugeNumber(input) &&
      (contains(f.detail, "/nearest/distance:") || contains(f.detail, "/best:")))
    return &kInfiniteNearestDistance;
  if (f.kind == "wrong-answer" && sizeIn(f.detail) >= 1e13) return &kFarFrameAngleFloor;
  return nullptr;
}

}  // namespace relpos::fuzz
