#include "convex_pieces.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "relpos/collision/scene.hpp"

namespace relpos::collision::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// More pieces than this and pairing them up costs more than FCL's hierarchy.
constexpr std::size_t kMaxPieces = 64;
// Facet normals closer than this (radians) are one direction; edges between such facets are
// diagonals of one face, not edges of the polytope.
constexpr double kSameDirection = 1e-10;
// Edge pairs closer to parallel than this give no axis (the face normals cover parallel edges;
// the cross product's direction would be mostly rounding).
constexpr double kParallelEdges = 1e-9;

bool sameAxis(const Vector3d& a, const Vector3d& b) { return a.cross(b).norm() < kSameDirection; }

// The connected pieces of a mesh: triangle indices per piece, vertices welded by position (STL
// files repeat them).
std::vector<std::vector<int>> pieceTriangles(const Mesh& m) {
  std::map<std::array<double, 3>, int> weld;
  std::vector<int> id(m.vertices.size());
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Vector3d& v = m.vertices[i];
    id[i] = weld.try_emplace({v.x(), v.y(), v.z()}, static_cast<int>(weld.size())).first->second;
  }
  std::vector<int> parent(weld.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& t : m.triangles)
    for (int k = 1; k < 3; ++k) parent[root(id[t[k]])] = root(id[t[0]]);
  std::map<int, std::vector<int>> by_root;
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    by_root[root(id[m.triangles[f][0]])].push_back(static_cast<int>(f));
  std::vector<std::vector<int>> pieces;
  for (auto& [r, tris] : by_root) pieces.push_back(std::move(tris));
  return pieces;
}

// The convex hull of points as vertices and outward triangles; false when it is not 3-D. (Through
// a Surface_mesh: CGAL 5.5's indexed-triangle-set output keeps the points lying on the hull's
// faces and edges — 96 vertices for a finely tessellated box instead of 8.)
bool hullOf(const std::vector<Vector3d>& points, std::vector<Vector3d>* vertices,
            std::vector<std::array<int, 3>>* faces) {
  std::vector<Kernel::Point_3> in;
  for (const auto& v : points) in.emplace_back(v.x(), v.y(), v.z());
  CGAL::Surface_mesh<Kernel::Point_3> hull;
  CGAL::convex_hull_3(in.begin(), in.end(), hull);
  if (hull.number_of_vertices() < 4 || hull.number_of_faces() < 4) return false;
  vertices->clear();
  faces->clear();
  for (auto v : hull.vertices()) {
    const auto& q = hull.point(v);
    vertices->emplace_back(q.x(), q.y(), q.z());
  }
  for (auto f : hull.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      if (k == 3) return false;  // not triangulated: never from convex_hull_3
      t[k++] = static_cast<int>(v.idx());
    }
    faces->push_back(t);
  }
  return true;
}

// Unit normal of a triangle, or zero for a sliver (collinear corners).
Vector3d facetNormal(const std::vector<Vector3d>& v, const std::array<int, 3>& f) {
  const Vector3d n = (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]);
  const double scale = (v[f[1]] - v[f[0]]).norm() * (v[f[2]] - v[f[0]]).norm();
  return n.norm() > 1e-12 * scale ? Vector3d(n.normalized()) : Vector3d::Zero();
}

double signedVolume(const std::vector<Vector3d>& v, const std::vector<std::array<int, 3>>& tris) {
  double six = 0;
  for (const auto& t : tris) six += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
  return six / 6.0;
}

// Cube-map cells of directions: face (dominant axis and its sign), then a kCells × kCells grid
// over the other two coordinates divided by the dominant one.
int cellOf(const Vector3d& u) {
  constexpr int kCells = ConvexPiece::kCells;
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(u[i]) > std::abs(u[k])) k = i;
  const double m = std::abs(u[k]);
  if (!(m > 0)) return 0;
  auto bin = [&](double x) {
    return std::min(kCells - 1, std::max(0, static_cast<int>((x / m + 1.0) * 0.5 * kCells)));
  };
  const int face = 2 * k + (u[k] < 0 ? 1 : 0);
  return (face * kCells + bin(u[(k + 1) % 3])) * kCells + bin(u[(k + 2) % 3]);
}

Vector3d cellDirection(int cell) {
  constexpr int kCells = ConvexPiece::kCells;
  const int face = cell / (kCells * kCells), i = cell / kCells % kCells, j = cell % kCells;
  const int k = face / 2;
  Vector3d u;
  u[k] = face % 2 ? -1.0 : 1.0;
  u[(k + 1) % 3] = (2.0 * (i + 0.5) / kCells - 1.0);
  u[(k + 2) % 3] = (2.0 * (j + 0.5) / kCells - 1.0);
  return u.normalized();
}

// The hull of one piece; false when it is not 3-D.
bool buildPiece(const Mesh& mesh, const std::vector<int>& tris, ConvexPiece* p) {
  Mesh sub;
  std::map<int, int> local;
  for (int f : tris) {
    std::array<int, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      auto [it, added] = local.try_emplace(v, static_cast<int>(sub.vertices.size()));
      if (added) sub.vertices.push_back(mesh.vertices[v]);
      t[k] = it->second;
    }
    sub.triangles.push_back(t);
  }
  std::vector<std::array<int, 3>> faces;
  if (!hullOf(sub.vertices, &p->vertices, &faces)) return false;

  Vector3d lo = p->vertices.front(), hi = lo;
  for (const auto& v : p->vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  p->centre = 0.5 * (lo + hi);
  for (const auto& v : p->vertices) p->radius = std::max(p->radius, (v - p->centre).norm());
  const double hull_volume = std::abs(signedVolume(p->vertices, faces));
  if (!(hull_volume > 1e-12 * std::pow(p->radius, 3))) return false;

  // Facet directions (with sign: coplanar facets share one) and axes (up to sign).
  std::vector<Vector3d> directions;
  std::vector<int> direction_of(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vector3d n = facetNormal(p->vertices, faces[f]);
    if (n.isZero()) {
      direction_of[f] = -1;  // a sliver: no direction, and its edges lie along real ones
      continue;
    }
    auto same = std::find_if(directions.begin(), directions.end(),
                             [&](const Vector3d& d) { return d.dot(n) > 0 && sameAxis(d, n); });
    direction_of[f] = static_cast<int>(same - directions.begin());
    if (same == directions.end()) directions.push_back(n);
  }
  for (const Vector3d& n : directions) {
    if (std::any_of(p->face_axes.begin(), p->face_axes.end(),
                    [&](const ConvexPiece::Axis& a) { return sameAxis(a.n, n); }))
      continue;
    ConvexPiece::Axis axis{n, std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
    for (const auto& v : p->vertices)
      axis.lo = std::min(axis.lo, n.dot(v)), axis.hi = std::max(axis.hi, n.dot(v));
    p->face_axes.push_back(axis);
  }

  // Edges: adjacency for climbing, and the directions of real (non-coplanar) edges.
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = faces[f][k], j = faces[f][(k + 1) % 3];
      edge_faces[{std::min(i, j), std::max(i, j)}].push_back(direction_of[f]);
    }
  std::vector<std::vector<int>> neighbours(p->vertices.size());
  for (const auto& [e, dirs] : edge_faces) {
    neighbours[e.first].push_back(e.second);
    neighbours[e.second].push_back(e.first);
    if (dirs.size() == 2 && (dirs[0] == dirs[1] || dirs[0] < 0 || dirs[1] < 0)) continue;
    const Vector3d d = (p->vertices[e.second] - p->vertices[e.first]).normalized();
    if (std::none_of(p->edge_directions.begin(), p->edge_directions.end(),
                     [&](const Vector3d& x) { return sameAxis(x, d); }))
      p->edge_directions.push_back(d);
  }
  p->first.push_back(0);
  for (const auto& nb : neighbours) {
    p->adjacent.insert(p->adjacent.end(), nb.begin(), nb.end());
    p->first.push_back(static_cast<int>(p->adjacent.size()));
  }
  constexpr int kCells = ConvexPiece::kCells;
  p->start.assign(6 * kCells * kCells, 0);
  for (int cell = 0; cell < 6 * kCells * kCells; ++cell) {
    const Vector3d u = cellDirection(cell);
    for (std::size_t i = 0; i < p->vertices.size(); ++i)
      if (u.dot(p->vertices[i]) > u.dot(p->vertices[p->start[cell]]))
        p->start[cell] = static_cast<int>(i);
  }

  // A convex solid: closed and consistently wound, every vertex on the hull's boundary, and the
  // hull's volume (a solid inside its hull with the same volume is the hull).
  classify(sub);
  if (!sub.oriented) return true;
  const double on_boundary = 1e-9 * (1.0 + p->radius + p->centre.norm());
  for (const auto& v : sub.vertices) {
    double outside = -std::numeric_limits<double>::infinity();
    for (const auto& a : p->face_axes)
      outside = std::max({outside, a.n.dot(v) - a.hi, a.lo - a.n.dot(v)});
    if (outside < -on_boundary) return true;
  }
  p->solid = std::abs(signedVolume(sub.vertices, sub.triangles)) >= (1 - 1e-9) * hull_volume;
  p->inner_depth = std::numeric_limits<double>::infinity();
  for (const auto& a : p->face_axes)
    p->inner_depth =
        std::min({p->inner_depth, a.hi - a.n.dot(p->centre), a.n.dot(p->centre) - a.lo});
  return true;
}

// How deep x (the piece's frame) lies in a convex solid piece: the distance to its nearest face
// plane, negative outside.
double depthIn(const ConvexPiece& p, const Vector3d& x) {
  double depth = std::numeric_limits<double>::infinity();
  for (const auto& a : p.face_axes) {
    const double d = a.n.dot(x);
    depth = std::min({depth, d - a.lo, a.hi - d});
  }
  return depth;
}

// Whether a point of p (posed by R, t in q's frame) lies in q with a depth, in p or in q, of more
// than `enough`: p's centre (at its inner depth) or one of its hull vertices.
bool deepPointIn(const ConvexPiece& p, const Matrix3d& R, const Vector3d& t, const ConvexPiece& q,
                 double enough) {
  const double d = depthIn(q, R * p.centre + t);
  if (d >= 0 && std::max(d, p.inner_depth) > enough) return true;
  for (const auto& v : p.vertices)
    if (depthIn(q, R * v + t) > enough) return true;
  return false;
}

// One piece pair: a posed by (R, t) in b's frame.
PiecesVerdict pairVerdict(const ConvexPiece& a, const Matrix3d& R, const Vector3d& t,
                          const ConvexPiece& b, double clearance, bool need_depth) {
  const double gap_needed = clearance > 0 ? clearance : -kTouchTolerance;
  const Vector3d a_centre = R * a.centre + t;
  // Rounding in the dot products: positions of this size, a few ulps each.
  const double scale = 1.0 + a_centre.norm() + b.centre.norm() + a.radius + b.radius;
  const double rounding = 1e-12 * scale;
  if ((a_centre - b.centre).norm() - a.radius - b.radius >= gap_needed + rounding)
    return {PiecesVerdict::kFree, 0.0};
  // The smallest overlap over the axes so far, and the rounding error of that axis' overlap.
  double min_overlap = std::numeric_limits<double>::infinity(), min_overlap_error = 0.0;
  // Whether an axis, with the two extents along it, proves the pair free. `error`: how far the
  // overlap may be off through rounding in the axis' direction and the dot products.
  auto separates = [&](double a_lo, double a_hi, double b_lo, double b_hi, double error) {
    const double gap = std::max(b_lo - a_hi, a_lo - b_hi);
    if (-gap < min_overlap) min_overlap = -gap, min_overlap_error = error;
    return gap >= gap_needed + error;
  };
  const Matrix3d Rt = R.transpose();
  for (const auto& axis : b.face_axes) {
    const Vector3d ua = Rt * axis.n;
    const double shift = axis.n.dot(t);
    if (separates(-a.support(-ua) + shift, a.support(ua) + shift, axis.lo, axis.hi, rounding))
      return {PiecesVerdict::kFree, 0.0};
  }
  for (const auto& axis : a.face_axes) {
    const Vector3d u = R * axis.n;
    const double shift = u.dot(t);
    if (separates(axis.lo + shift, axis.hi + shift, -b.support(-u), b.support(u), rounding))
      return {PiecesVerdict::kFree, 0.0};
  }
  // A deep common point proves a collision without the edge axes (when the depth is not asked for):
  // if p lies in both, moving a by less than p's depth in either cannot separate them. The
  // points tried: each piece's centre and hull vertices, inside the other.
  if (!need_depth && a.solid && b.solid) {
    const double enough = kTouchTolerance + 1e-8 * scale;
    if (deepPointIn(a, R, t, b, enough)) return {PiecesVerdict::kCollides, enough};
    if (deepPointIn(b, Rt, -(Rt * t), a, enough)) return {PiecesVerdict::kCollides, enough};
  }
  for (const Vector3d& ea : a.edge_directions) {
    const Vector3d ra = R * ea;
    for (const Vector3d& eb : b.edge_directions) {
      Vector3d u = ra.cross(eb);
      const double s = u.norm();
      if (s < kParallelEdges) continue;
      u /= s;
      const Vector3d ua = Rt * u;
      const double shift = u.dot(t);
      // Normalising a short cross product magnifies its rounding by 1/s.
      const double error = rounding + 4e-16 / s * scale;
      if (separates(-a.support(-ua) + shift, a.support(ua) + shift, -b.support(-u), b.support(u),
                    error))
        return {PiecesVerdict::kFree, 0.0};
    }
  }
  // Every candidate axis overlaps: for two convex solids the smallest overlap is the penetration
  // depth. The margin covers that axis' rounding and the axes left out: directions within
  // kSameDirection merged, edge pairs parallel within kParallelEdges skipped.
  const double margin = min_overlap_error + (kSameDirection + kParallelEdges) * scale;
  if (a.solid && b.solid && min_overlap > kTouchTolerance + margin)
    return {PiecesVerdict::kCollides, min_overlap};
  return {PiecesVerdict::kUnknown, 0.0};
}

}  // namespace

double ConvexPiece::support(const Vector3d& u) const {
  if (vertices.size() <= 16) {
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& v : vertices) best = std::max(best, u.dot(v));
    return best;
  }
  int v = start[cellOf(u)];
  double best = u.dot(vertices[v]);
  // A linear function's local maximum on a convex polytope's vertex graph is the maximum.
  for (bool moved = true; moved;) {
    moved = false;
    int next = v;
    for (int j = first[v]; j < first[v + 1]; ++j) {
      const double d = u.dot(vertices[adjacent[j]]);
      if (d > best) best = d, next = adjacent[j], moved = true;
    }
    v = next;
  }
  return best;
}

std::vector<ConvexPiece> convexPieces(const Mesh& mesh) {
  const auto groups = pieceTriangles(mesh);
  if (groups.size() > kMaxPieces) return {};
  std::vector<ConvexPiece> pieces(groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i)
    if (!buildPiece(mesh, groups[i], &pieces[i])) return {};
  // Pieces of one mesh that overlap (a shell inside another: a hollow solid, whose cavity is
  // outside it) are not solids of their own: the solid is what the crossings' parity says, which
  // FCL's path and the inside test decide. Their hulls still prove poses free.
  const Matrix3d I = Matrix3d::Identity();
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (pairVerdict(pieces[i], I, Vector3d::Zero(), pieces[j], 0.0, true).kind !=
          PiecesVerdict::kFree)
        pieces[i].solid = pieces[j].solid = false;
  return pieces;
}

PiecesVerdict piecesVerdict(const std::vector<ConvexPiece>& a, const Isometry3d& X_WA,
                            const std::vector<ConvexPiece>& b, const Isometry3d& X_WB,
                            double clearance, bool need_depth) {
  if (a.empty() || b.empty()) return {};
  const Isometry3d T = X_WB.inverse() * X_WA;
  const Matrix3d R = T.linear();
  const Vector3d t = T.translation();
  PiecesVerdict all{PiecesVerdict::kFree, 0.0};
  for (const auto& pa : a)
    for (const auto& pb : b) {
      const PiecesVerdict v = pairVerdict(pa, R, t, pb, clearance, need_depth);
      if (v.kind == PiecesVerdict::kCollides && !need_depth) return v;
      if (v.kind == PiecesVerdict::kCollides) {
        all.depth = std::max(all.depth, v.depth);
        all.kind = PiecesVerdict::kCollides;
      } else if (v.kind == PiecesVerdict::kUnknown && all.kind == PiecesVerdict::kFree) {
        all.kind = PiecesVerdict::kUnknown;
      }
    }
  return all;
}

}  // namespace relpos::collision::detail
