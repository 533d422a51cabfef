#include "centring.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace relpos::detail {
namespace {

// Running bounding box of points.
struct Box {
  Vector3d lo = Vector3d::Constant(std::numeric_limits<double>::infinity());
  Vector3d hi = Vector3d::Constant(-std::numeric_limits<double>::infinity());
  void grow(const Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool empty() const { return !(lo.x() <= hi.x()); }
  // The middle (not the centroid: it does not depend on the order of the constraints).
  Vector3d middle() const { return empty() ? Vector3d::Zero() : Vector3d(0.5 * (lo + hi)); }
  double magnitude() const {
    return empty() ? 0.0 : std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  }
  // The box's diagonal: no two of its points are further apart, so an angle within the angle
  // tolerance never moves one point's reading of another (a lever at most this long) by more than
  // the length tolerance: nearly parallel is then also nearly coincident.
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
};

bool isCustom(const Fundamental& f) { return f.kind == FundamentalKind::kCustom; }

}  // namespace

Centring centreSets(std::vector<ConstraintSet>& sets, bool centre) {
  Centring c;
  Box fixed, mobile;
  double values = 0.0;
  bool custom = false;
  for (ConstraintSet& set : sets)
    for (auto* list : {&set.translational, &set.rotational})
      for (Fundamental& f : *list) {
        custom = custom || isCustom(f);
        if (const Vector3d* p = f.fixedPoint()) fixed.grow(*p);
        if (const Vector3d* p = f.mobilePoint()) mobile.grow(*p);
        if (f.translational() && !isCustom(f))
          for (double v : {f.lo, f.hi})
            if (std::isfinite(v)) values = std::max(values, std::abs(v));
      }
  c.magnitude = std::max(fixed.magnitude(), mobile.magnitude());
  c.centred = centre && !custom;
  if (c.centred) {
    c.offset_W = fixed.middle();
    c.offset_M = mobile.middle();
    for (ConstraintSet& set : sets)
      for (Fundamental& f : set.translational) f.translate(-c.offset_W, -c.offset_M);
  }
  // Uncentred, the coordinates themselves are the lengths the rules compute with.
  const double extent = c.centred ? std::max(fixed.diagonal(), mobile.diagonal()) : c.magnitude;
  c.size = std::max(extent, values);
  return c;
}

double placementMagnitude(const Problem& problem) {
  const Vector3d& t = problem.fixed.pose.translation();
  double m = t.cwiseAbs().maxCoeff();
  if (!(m > 0.0))
    return m;  // at the origin (or NaN, which outOfRange reports) placing adds nothing
  for (const InputConstraint& c : problem.constraints)
    m = std::max(m, c.fixed.point.cwiseAbs().maxCoeff());
  return m;
}

Tolerance toleranceFor(const Centring& c, double relative_length, double angle) {
  // 64 ulps of the largest coordinate: the input's own rounding (half an ulp each), its placement
  // by the fixed pose and the centring (a few ulps), with room for the rules' arithmetic.
  constexpr double kRoundingUlps = 64 * std::numeric_limits<double>::epsilon();
  Tolerance t;
  t.length = std::max(relative_length * c.size, kRoundingUlps * c.magnitude);
  // (Directions read off coordinates carry their rounding over the span they are read from: the
  // rules that derive them say so in Fundamental::err, from the length tolerance above. Given
  // directions are unit vectors a pose turns, as precise anywhere.)
  t.angle = angle;
  // Rounding magnified a thousandfold is still ~1e-13 of the size, far below the tolerance; more
  // waits for the pairs that decide better (solver.cpp).
  t.max_amplification = kConditioningBound;
  return t;
}

std::string tooFarFromOrigin(const Centring& c, const Tolerance& decided, double relative_length) {
  // (A problem of no extent has no lengths to decide but at its one point.)
  const double asked = relative_length * c.size;
  if (!(c.size > 0.0) || !(decided.length > kMaxRoundingWidening * asked)) return std::string();
  char why[240];
  std::snprintf(why, sizeof why,
                "coordinates of %.3g for a problem of size %.3g: their rounding (%.3g) exceeds the "
                "length tolerance asked for (%.3g) more than %.0f-fold; express the features "
                "nearer their frames' origins",
                c.magnitude, c.size, decided.length, asked, kMaxRoundingWidening);
  return why;
}

const char* outOfRange(const Centring& c, const Problem& problem) {
  if (!std::isfinite(c.size) || !std::isfinite(c.magnitude))
    return "a coordinate or value is not finite";
  if (c.magnitude > 1e100 || c.size > 1e100)
    return "coordinates or lengths beyond 1e100 (their squares would overflow): scale the problem";
  if (c.size > 0.0 && c.size < 1e-100)
    return "the geometry spans less than 1e-100 (its squares would underflow): scale the problem";
  if (!(problem.mobile.pose.translation().cwiseAbs().maxCoeff() <= 1e100))
    return "the mobile object's initial pose lies beyond 1e100: scale the problem";
  return nullptr;
}

}  // namespace relpos::detail
