#pragma once
// Exact verdicts for most poses without FCL: each connected piece of a mesh is bounded by its
// convex hull, and two hulls are tested with the separating-axis theorem.
//
// Why: a part resting on a table touches it over a whole face; FCL then visits every pair of
// nearby triangles of the two finely tessellated faces to prove they do not cross (150–600 µs a
// pose at 10k triangles). The table's top face is one separating axis of the two hulls: a few
// dot products prove the pose free.
//
// - Free: some axis separates the hulls (or overlaps them by at most kTouchTolerance, or leaves
//   the clearance): the pieces inside them cannot interpenetrate more. Exact for any mesh.
// - Colliding: when both pieces *are* their hulls (closed, wound consistently, every vertex on
//   the hull, the same volume), the smallest overlap over the complete set of candidate axes
//   (face normals of both, cross products of edge directions) is their penetration depth; more
//   than kTouchTolerance (plus a rounding margin) is a collision, with that depth.
// - Anything else (a non-convex piece whose hull overlaps, a depth within the margin, a
//   clearance the axes cannot prove) is left to FCL.
#include <vector>

#include "relpos/collision/mesh.hpp"

namespace relpos::collision::detail {

// One connected piece of a mesh as its convex hull.
struct ConvexPiece {
  std::vector<Vector3d> vertices;  // the hull's vertices
  // Hull edges as adjacency lists (CSR): neighbours of vertex i are
  // adjacent[first[i] .. first[i + 1]). A linear function's maximum over a convex polytope is
  // found by climbing edges.
  std::vector<int> first, adjacent;
  struct Axis {
    Vector3d n;     // unit facet normal (one per direction, up to sign)
    double lo, hi;  // this piece's extent along n
  };
  std::vector<Axis> face_axes;
  // Unit, up to sign; edges between coplanar facets (diagonals of one face) left out.
  std::vector<Vector3d> edge_directions;
  Vector3d centre = Vector3d::Zero();
  double radius = 0.0;
  bool solid = false;  // the piece is exactly its hull (a convex solid)
  // Where climbing starts: the extreme vertex for the centre direction of the cube-map cell the
  // query direction falls in (6 faces × kCells² cells), so that it takes a step or two.
  static constexpr int kCells = 4;
  std::vector<int> start;
  double inner_depth = 0.0;  // solid: depth of `centre` inside the piece (distance to its faces)

  double support(const Vector3d& u) const;  // max of u·v over the piece
};

// The pieces of a mesh, or none when some piece has no 3-D hull (flat or a lone edge) or there are
// too many pieces to pair up: then every verdict is left to FCL.
std::vector<ConvexPiece> convexPieces(const Mesh& mesh);

struct PiecesVerdict {
  enum Kind { kFree, kCollides, kUnknown } kind = kUnknown;
  double depth = 0.0;  // kCollides: the deepest penetration found between two pieces
};

// Mesh A at X_WA against mesh B at X_WB, both given as pieces. Without `need_depth` a collision
// may be proved by a deep common point alone (and its depth is then a lower bound).
PiecesVerdict piecesVerdict(const std::vector<ConvexPiece>& a, const Isometry3d& X_WA,
                            const std::vector<ConvexPiece>& b, const Isometry3d& X_WB,
                            double clearance, bool need_depth);

}  // namespace relpos::collision::detail
