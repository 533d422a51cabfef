#include "unmatched_hint.hpp"

#include "relpos/core/constraint_text.hpp"

#include <cstdio>
#include <set>
#include <vector>

namespace relpos::detail {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A value in the spec's units: an angle in degrees when the spec's were.
std::string quantity(const Problem& p, const ConstraintType* type, double v) {
  if (type && type->value_kind == ValueKind::kAngle && p.angles_in_degrees)
    return number(v * 180.0 / kPi) + "°";
  return number(v);
}

std::string valueText(const Problem& p, const ConstraintType* type, const InputConstraint& c) {
  if (!type || type->value_kind == ValueKind::kNone) return "";
  if (!c.isRange()) return ", " + quantity(p, type, c.value);
  const bool lo = std::isfinite(c.min), hi = std::isfinite(c.max);
  if (lo && hi) return ", " + quantity(p, type, c.min) + " to " + quantity(p, type, c.max);
  if (lo) return ", at least " + quantity(p, type, c.min);
  if (hi) return ", at most " + quantity(p, type, c.max);
  return "";
}

// The constraints of mask `which` (the first 64).
std::vector<std::size_t> listed(const Problem& p, SourceMask which) {
  std::vector<std::size_t> list;
  for (std::size_t i = 0; i < p.constraints.size() && i < 64; ++i)
    if (which >> i & 1) list.push_back(i);
  return list;
}

// The hint for the pattern the constraints form, the commonest first.
std::string hint(const Problem& p, const std::vector<std::size_t>& involved) {
  int ranges = 0;
  std::set<std::string> mobile_points;
  for (std::size_t i : involved) {
    const InputConstraint& c = p.constraints[i];
    ranges += c.isRange();
    if (c.mobile.kind == FeatureKind::kPoint) mobile_points.insert(c.mobile_name);
  }
  if (ranges > 0)
    return "A range is combined in closed form with one other angle on the same mobile axis, a "
           "parallelism, or point-plane and point-line constraints on the same point (docs/spec.md "
           "§1.10, §2.11): stating a range as an exact value (min = max), or on the mobile feature "
           "another constraint already holds, may let the rules solve it.";
  if (mobile_points.size() >= 2)
    return "Constraints on different mobile points leave the rotation between them free: a "
           "constraint the task implies that fixes the mobile object's rotation (a parallelism, a "
           "coincident line or plane), or stating them on one point, lets the rules solve it.";
  return "No rule combines these: a redundant constraint the task already implies (a "
         "coincidence, a parallelism, a fixed angle) may let the rules solve it.";
}

}  // namespace

std::string explainUnmatched(const Problem& problem, const Registry& registry,
                             SourceMask involved) {
  const std::vector<std::size_t> list = listed(problem, involved);
  if (list.empty()) return "";
  return "of " + describeConstraints(problem, registry, involved) + ". " + hint(problem, list);
}

}  // namespace relpos::detail

namespace relpos {

std::string describeConstraint(const Problem& p, const Registry& registry, std::size_t i) {
  const InputConstraint& c = p.constraints[i];
  const ConstraintType* type = registry.constraintType(c.type);
  std::string s = std::to_string(i);
  if (!c.id.empty()) s += " '" + c.id + "'";
  return s + " (" + c.type + " " + c.fixed_name + "–" + c.mobile_name +
         detail::valueText(p, type, c) + ")";
}

std::string describeConstraints(const Problem& problem, const Registry& registry,
                                SourceMask which) {
  const std::vector<std::size_t> list = detail::listed(problem, which);
  std::string s;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (k > 0) s += k + 1 == list.size() ? " and " : ", ";
    s += describeConstraint(problem, registry, list[k]);
  }
  return s;
}

}  // namespace relpos
