#include "solid_inside.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <vector>

namespace relpos::collision::detail {
namespace {
using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
}  // namespace

struct SolidInside::Tree {
  Triangles triangles;
  AabbTree tree;
};

SolidInside::SolidInside(const Mesh& m) : tree_(std::make_unique<Tree>()) {
  auto point = [&](int i) {
    const Vector3d& v = m.vertices[static_cast<std::size_t>(i)];
    return K::Point_3(v.x(), v.y(), v.z());
  };
  for (const auto& t : m.triangles)
    tree_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
  lo_ = hi_ = m.vertices.front();
  for (const auto& v : m.vertices) lo_ = lo_.cwiseMin(v), hi_ = hi_.cwiseMax(v);
  ray_start_ = 1e-9 * (1.0 + (hi_ - lo_).norm());
}

SolidInside::~SolidInside() = default;

bool SolidInside::operator()(const Vector3d& p) const {
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return false;
  // A fixed direction chosen to miss the edges and vertices of ordinary (axis-aligned, regular)
  // meshes.
  const Vector3d dir = Vector3d(0.5772156649, 0.3183098862, 0.7548776662).normalized();
  const Vector3d start = p + ray_start_ * dir;
  const K::Ray_3 ray(K::Point_3(start.x(), start.y(), start.z()),
                     K::Vector_3(dir.x(), dir.y(), dir.z()));
  return tree_->tree.number_of_intersected_primitives(ray) % 2 == 1;
}

}  // namespace relpos::collision::detail
