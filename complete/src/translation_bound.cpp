#include "translation_bound.hpp"

#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace relpos::complete::detail {

Bound boundingBox(const std::vector<Slab>& slabs, double margin, Vector3d* lo, Vector3d* hi) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  *lo = Vector3d::Constant(-kInf);
  *hi = Vector3d::Constant(kInf);
  const int m = static_cast<int>(slabs.size());
  // a slab across an axis bounds that coordinate alone
  for (const Slab& s : slabs)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      if (s.n[j] != 0.0 || s.n[k] != 0.0 || s.n[i] == 0.0) continue;
      const double a = s.lo / s.n[i], b = s.hi / s.n[i];
      (*lo)[i] = std::max((*lo)[i], std::min(a, b));
      (*hi)[i] = std::min((*hi)[i], std::max(a, b));
    }
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      for (int c = b + 1; c < m; ++c) {
        Eigen::Matrix3d N;
        N.row(0) = slabs[a].n.transpose();
        N.row(1) = slabs[b].n.transpose();
        N.row(2) = slabs[c].n.transpose();
        if (!(std::abs(N.determinant()) > 1e-3 * N.rowwise().norm().prod())) continue;
        const Eigen::Matrix3d inv = N.inverse();
        const int k[3] = {a, b, c};
        for (int i = 0; i < 3; ++i) {
          double low = 0.0, high = 0.0;
          for (int j = 0; j < 3; ++j) {
            const double x = inv(i, j) * slabs[k[j]].lo, y = inv(i, j) * slabs[k[j]].hi;
            low += std::min(x, y);
            high += std::max(x, y);
          }
          (*lo)[i] = std::max((*lo)[i], low);
          (*hi)[i] = std::min((*hi)[i], high);
        }
      }
  bool empty = false, unbounded = false;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite((*lo)[i]) || !std::isfinite((*hi)[i])) {
      unbounded = true;
      continue;
    }
    const double slack = 1e-6 * (1.0 + std::abs((*lo)[i]) + std::abs((*hi)[i])) + margin;
    (*lo)[i] -= slack;
    (*hi)[i] += slack;
    empty = empty || (*lo)[i] > (*hi)[i];
  }
  return empty ? Bound::kEmpty : unbounded ? Bound::kUnbounded : Bound::kBox;
}

void ballSlabs(const Vector3d& centre, double radius, std::vector<Slab>* out, int source) {
  for (int i = 0; i < 3; ++i)
    out->push_back({Vector3d::Unit(i), centre[i] - radius, centre[i] + radius, source});
}

}  // namespace relpos::complete::detail
