#include "relpos/manifolds/catalogue.hpp"

#include <string>
#include <variant>

#include "relpos/manifolds/line_distance.hpp"
#include "relpos/manifolds/radial_grasp.hpp"
#include "relpos/manifolds/revolved.hpp"
#include "relpos/manifolds/rotation/shapes.hpp"
#include "relpos/manifolds/translation/shapes.hpp"

namespace relpos::manifolds {
namespace {

template <typename... T>
struct TypeList {};

// The mixed manifolds: a new one is one line here.
using MixedManifolds = TypeList<LineDistanceManifold,  //
                                RadialGraspManifold,   //
                                RevolvedManifold>;

void addEntry(std::vector<ManifoldInfo>& out, const std::string& name, const char* summary) {
  for (ManifoldInfo& m : out)
    if (m.name == name) {
      m.description += std::string("; ") + summary;
      return;
    }
  out.push_back({name, summary});
}

template <typename... Shape>
void addShapes(std::vector<ManifoldInfo>& out, const char* prefix, const std::variant<Shape...>*) {
  (addEntry(out, std::string(prefix) + Shape::kName, Shape::kSummary), ...);
}

template <typename... Mixed>
void addMixed(std::vector<ManifoldInfo>& out, TypeList<Mixed...>) {
  (addEntry(out, std::string("mixed/") + Mixed::kTypeName, Mixed::kSummary), ...);
}

}  // namespace

std::vector<ManifoldInfo> separableShapeCatalogue() {
  std::vector<ManifoldInfo> out;
  addShapes(out, "rotation/", static_cast<const RotationShape*>(nullptr));
  addShapes(out, "translation/", static_cast<const TranslationShape*>(nullptr));
  return out;
}

std::vector<ManifoldInfo> mixedManifoldCatalogue() {
  std::vector<ManifoldInfo> out;
  addMixed(out, MixedManifolds{});
  return out;
}

std::vector<ManifoldInfo> builtinManifoldCatalogue() {
  std::vector<ManifoldInfo> out = separableShapeCatalogue();
  for (ManifoldInfo& m : mixedManifoldCatalogue()) out.push_back(std::move(m));
  return out;
}

}  // namespace relpos::manifolds
