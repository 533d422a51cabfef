// The registry's manifold catalogue (manifolds/src/catalogue.cpp) is what is built in: every
// shape of the rotation and translation variants, and every mixed manifold, is listed under the
// name results write.
#include "relpos/manifolds/catalogue.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>
#include <vector>

#include "relpos/builtins/builtins.hpp"
#include "relpos/manifolds/line_distance.hpp"
#include "relpos/manifolds/radial_grasp.hpp"
#include "relpos/manifolds/revolved.hpp"
#include "relpos/manifolds/rotation_part.hpp"
#include "relpos/manifolds/translation_part.hpp"

namespace relpos::test {
namespace {

std::set<std::string> registeredNames() {
  std::set<std::string> names;
  for (const ManifoldInfo& m : builtinRegistry().manifolds()) names.insert(m.name);
  return names;
}

// The names the variant's shapes write, prefixed.
template <typename... Shape>
std::vector<std::string> shapeNames(const std::string& prefix, const std::variant<Shape...>*) {
  return {(prefix + Shape::kName)...};
}

TEST(Catalogue, EveryShapeInTheVariantsIsRegistered) {
  const std::set<std::string> names = registeredNames();
  for (const std::string& name :
       shapeNames("rotation/", static_cast<const manifolds::RotationShape*>(nullptr)))
    EXPECT_EQ(names.count(name), 1u) << name;
  for (const std::string& name :
       shapeNames("translation/", static_cast<const manifolds::TranslationShape*>(nullptr)))
    EXPECT_EQ(names.count(name), 1u) << name;
  EXPECT_EQ(std::variant_size_v<manifolds::RotationShape>, 8u);
  EXPECT_EQ(std::variant_size_v<manifolds::TranslationShape>, 15u);
}

TEST(Catalogue, EveryMixedManifoldIsRegistered) {
  const std::set<std::string> names = registeredNames();
  for (const char* type :
       {manifolds::LineDistanceManifold::kTypeName, manifolds::RadialGraspManifold::kTypeName,
        manifolds::RevolvedManifold::kTypeName})
    EXPECT_EQ(names.count(std::string("mixed/") + type), 1u) << type;
}

TEST(Catalogue, RegisteredIsExactlyTheCatalogue) {
  const std::vector<ManifoldInfo> catalogue = manifolds::builtinManifoldCatalogue();
  const auto& registered = builtinRegistry().manifolds();
  ASSERT_EQ(registered.size(), catalogue.size());
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    EXPECT_EQ(registered[i].name, catalogue[i].name);
    EXPECT_FALSE(catalogue[i].description.empty()) << catalogue[i].name;
  }
}

TEST(Catalogue, ShapesWritingOneNameShareAnEntry) {
  // A line of two planes is written "Line", as a point on a line is: one entry, both summaries.
  for (const ManifoldInfo& m : manifolds::separableShapeCatalogue())
    if (m.name == "translation/Line") {
      EXPECT_NE(m.description.find(manifolds::translation::Line::kSummary), std::string::npos);
      EXPECT_NE(m.description.find(manifolds::translation::LineOfPlanes::kSummary),
                std::string::npos);
    }
}

}  // namespace
}  // namespace relpos::test
