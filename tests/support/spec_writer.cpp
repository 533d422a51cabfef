#include "spec_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "relpos/io/spec_reader.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

// Ordered: the written spec keeps its keys in the order a person writes them.
using OrderedJson = nlohmann::ordered_json;

OrderedJson vec(const Vector3d& v) { return OrderedJson::array({v.x(), v.y(), v.z()}); }

OrderedJson poseJson(const Isometry3d& X) {
  const Quaterniond q(X.linear());
  return {{"position", vec(X.translation())},
          {"orientation", OrderedJson::array({q.x(), q.y(), q.z(), q.w()})}};
}

OrderedJson featureJson(const Feature& f) {
  switch (f.kind) {
    case FeatureKind::kPoint:
      return {{"point", vec(f.point)}};
    case FeatureKind::kLine:
      return {{"line", {{"point", vec(f.point)}, {"direction", vec(f.direction)}}}};
    case FeatureKind::kPlane:
      return {{"plane", {{"point", vec(f.point)}, {"normal", vec(f.direction)}}}};
    case FeatureKind::kCylinder:
      return {{"cylinder",
               {{"point", vec(f.point)}, {"direction", vec(f.direction)}, {"radius", f.radius}}}};
  }
  return nullptr;
}

OrderedJson objectJson(const ObjectSpec& o) {
  OrderedJson features = OrderedJson::object();
  for (const NamedFeature& f : o.features) features[f.name] = featureJson(f.feature);
  return {{"name", o.name}, {"pose", poseJson(o.pose)}, {"features", features}};
}

OrderedJson constraintJson(const InputConstraint& c) {
  OrderedJson j = {{"type", c.type}, {"fixed", c.fixed_name}, {"mobile", c.mobile_name}};
  if (!c.id.empty()) j["id"] = c.id;
  const ConstraintType* type = builtinRegistry().constraintType(c.type);
  if (!type || type->takes_value) {
    if (c.has_value) {
      j["value"] = c.value;
    } else {
      // A one-sided range is written with its finite side only (SPEC: open on the other).
      if (std::isfinite(c.min)) j["min"] = c.min;
      if (std::isfinite(c.max)) j["max"] = c.max;
    }
  }
  j["orientation"] = toString(c.orientation);
  if (!c.parallel) j["parallel"] = false;
  return j;
}

}  // namespace

std::string specJson(const Problem& p) {
  OrderedJson constraints = OrderedJson::array();
  for (const InputConstraint& c : p.constraints) constraints.push_back(constraintJson(c));
  const OrderedJson doc = {{"relpos", 1},
                    {"name", p.name},
                    {"units", {{"angle", "rad"}}},
                    {"fixed", objectJson(p.fixed)},
                    {"mobile", objectJson(p.mobile)},
                    {"constraints", constraints}};
  return doc.dump();
}

WrittenSpec written(const Problem& p) {
  WrittenSpec w{specJson(p), p};
  ParseResult r = parseSpec(w.text, builtinRegistry(), p.name);
  if (!r.problem) {
    ADD_FAILURE() << "spec writer: " << (r.errors.empty() ? "" : r.errors.front().path) << ": "
                  << (r.errors.empty() ? "?" : r.errors.front().message) << "\n"
                  << w.text;
    return w;
  }
  w.problem = std::move(*r.problem);
  return w;
}

}  // namespace relpos::test
