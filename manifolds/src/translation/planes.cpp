#include "relpos/manifolds/translation/planes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace relpos::manifolds::translation {
namespace {

// What the projection reads off the rows besides their heights: the directions along every
// plane, and whether the normals are mutually orthogonal.
void finishRows(PlaneRows* rows) {
  if (rows->k == 2) rows->free[0] = rows->n[0].cross(rows->n[1]).normalized();
  if (rows->k == 1) {
    rows->free[0] = rows->e1;
    rows->free[1] = rows->n[0].cross(rows->e1);
  }
  rows->orthogonal = true;
  for (int i = 0; i < rows->k && rows->orthogonal; ++i)
    for (int j = 0; j < i && rows->orthogonal; ++j)
      rows->orthogonal =
          std::abs(rows->n[i].dot(rows->n[j])) <= 1e-12 * rows->n[i].norm() * rows->n[j].norm();
}

PlaneRows planeRowsFor(const FixedVector<Fundamental, 3>& linear, const Matrix3d& R) {
  PlaneRows rows;
  int n_ranged = 0;
  auto add = [&](const Vector3d& n, double h0, double sign, int ranged) {
    if (rows.k == 3) return;
    rows.n[rows.k] = n;
    rows.h0[rows.k] = h0;
    rows.sign[rows.k] = sign;
    rows.ranged[rows.k] = ranged;
    ++rows.k;
  };
  for (const Fundamental& f : linear) {
    switch (f.kind) {
      case FundamentalKind::kPointPlane: {
        // The in-plane direction only for a lone plane (k = 1), the one case that needs it.
        Vector3d c, d;
        planeOf(f, R, &c, &d);
        if (linear.size() == 1) rows.e1 = shapeOf(f, R).e1;
        add(d, d.dot(c), f.point_side == Side::kMobile ? 1.0 : -1.0, f.exact() ? -1 : n_ranged++);
        break;
      }
      case FundamentalKind::kPointLine: {  // exact, on the line: two planes through it
        const TShape s = shapeOf(f, R);
        const Vector3d e2 = s.d.cross(s.e1);
        add(s.e1, s.e1.dot(s.c), 1.0, -1);
        add(e2, e2.dot(s.c), 1.0, -1);
        break;
      }
      case FundamentalKind::kPointPoint: {  // exact, pinned: three planes
        const TShape s = shapeOf(f, R);
        for (int a = 0; a < 3; ++a) add(Vector3d::Unit(a), s.c[a], 1.0, -1);
        break;
      }
      case FundamentalKind::kAngle:
      case FundamentalKind::kLineLine:
      case FundamentalKind::kCustom:
        break;
    }
  }
  finishRows(&rows);
  return rows;
}

// The point of {x : n[i]·x = h[i], i < m} nearest the origin, x = Nᵀ (N Nᵀ)⁻¹ h, with fixed-size
// matrices so evaluating a pose never allocates (the rows are independent: the matcher checked).
Vector3d flatPoint(const Vector3d* n, const double* h, int m) {
  if (m == 0) return Vector3d::Zero();
  if (m == 1) return n[0] * (h[0] / n[0].squaredNorm());
  if (m == 2) {
    Eigen::Matrix2d G;
    G << n[0].dot(n[0]), n[0].dot(n[1]), n[1].dot(n[0]), n[1].dot(n[1]);
    const Eigen::Vector2d l = G.inverse() * Eigen::Vector2d(h[0], h[1]);
    return l[0] * n[0] + l[1] * n[1];
  }
  // Three rows: their one common point, by Cramer's rule in cross products.
  const Vector3d c12 = n[1].cross(n[2]), c20 = n[2].cross(n[0]), c01 = n[0].cross(n[1]);
  return (h[0] * c12 + h[1] * c20 + h[2] * c01) / n[0].dot(c12);
}

// T on every plane at the given range values.
Vector3d planesPoint(const PlaneRows& rows, const double* v) {
  double h[3];
  for (int i = 0; i < rows.k; ++i)
    h[i] = rows.h0[i] + (rows.ranged[i] >= 0 ? rows.sign[i] * v[rows.ranged[i]] : 0.0);
  return flatPoint(rows.n, h, rows.k);
}

// The projection of T onto the flat where rows `active` (a bit mask) hold n·x = b.
Vector3d ontoFlat(const PlaneRows& rows, unsigned active, const double* b, const Vector3d& T) {
  Vector3d n[3];
  double r[3];
  int m = 0;
  for (int i = 0; i < rows.k; ++i)
    if (active & (1u << i)) n[m] = rows.n[i], r[m] = rows.n[i].dot(T) - b[i], ++m;
  return T - flatPoint(n, r, m);
}

// The point of the set (exact rows held, ranged rows within their bounds) nearest T: every way
// of holding each ranged row at a bound or leaving it free (at most 3³), each the projection of T
// onto its flat; the nearest that keeps the free rows within bounds is the answer, since the
// optimum's own active set is among them. (Clamping the heights one by one is exact only for
// orthogonal rows.)
Vector3d nearestOnRows(const PlaneRows& rows, const FixedVector<Fundamental, 3>& linear,
                       const Vector3d& T) {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  unsigned ranged = 0, exact = 0;
  const Fundamental* by_range[3] = {nullptr, nullptr, nullptr};
  int r = 0;
  for (const Fundamental& f : linear)
    if (!f.exact()) by_range[r++] = &f;
  for (int i = 0; i < rows.k; ++i) {
    if (rows.ranged[i] < 0) {
      exact |= 1u << i;
      lo[i] = hi[i] = rows.h0[i];
      continue;
    }
    ranged |= 1u << i;
    const Fundamental& f = *by_range[rows.ranged[i]];
    const double a = rows.h0[i] + rows.sign[i] * f.lo, b = rows.h0[i] + rows.sign[i] * f.hi;
    lo[i] = std::min(a, b), hi[i] = std::max(a, b);
  }
  // Mutually orthogonal rows (a box; a seam, its two planes, and a range across its ends): each
  // row's height moves along its own normal only, so clamping each on its own is the nearest
  // point, with no active set to search.
  if (rows.orthogonal) {
    Vector3d x = T;
    for (int i = 0; i < rows.k; ++i) {
      const double h = rows.n[i].dot(T);
      const double target = std::min(hi[i], std::max(lo[i], h));
      x += ((target - h) / rows.n[i].squaredNorm()) * rows.n[i];
    }
    return x;
  }
  Vector3d best = T;
  double best_d = std::numeric_limits<double>::infinity();
  int combos = 1;
  for (int i = 0; i < rows.k; ++i)
    if (ranged & (1u << i)) combos *= 3;
  for (int c = 0; c < combos; ++c) {
    unsigned active = exact;
    double b[3] = {lo[0], lo[1], lo[2]};
    for (int i = 0, code = c; i < rows.k; ++i) {
      if (!(ranged & (1u << i))) continue;
      const int state = code % 3;  // 0: free, 1: at lo, 2: at hi
      code /= 3;
      if (state == 0) continue;
      active |= 1u << i;
      b[i] = state == 1 ? lo[i] : hi[i];
    }
    const Vector3d x = ontoFlat(rows, active, b, T);
    bool inside = true;
    for (int i = 0; i < rows.k && inside; ++i) {
      if (!(ranged & (1u << i)) || (active & (1u << i))) continue;
      const double h = rows.n[i].dot(x), slack = kUnitRounding * (1.0 + std::abs(h));
      inside = h >= lo[i] - slack && h <= hi[i] + slack;
    }
    const double d = (x - T).squaredNorm();
    // No ranged row held and all within bounds: the projection onto the exact rows' flat, which
    // is nearer than any point of the set.
    if (inside && c == 0) return x;
    if (inside && d < best_d) best_d = d, best = x;
  }
  return best;
}

}  // namespace

// planeRowsFor's count without its geometry (dof() and parameter() ask for it on every call):
// one row a plane, two a line, three a pinned point, at most three.
int Planes::planeRows() const {
  int k = 0;
  for (const Fundamental& f : linear) {
    switch (f.kind) {
      case FundamentalKind::kPointPlane:
        k += 1;
        break;
      case FundamentalKind::kPointLine:
        k += 2;
        break;
      case FundamentalKind::kPointPoint:
        k += 3;
        break;
      case FundamentalKind::kAngle:
      case FundamentalKind::kLineLine:
      case FundamentalKind::kCustom:
        break;
    }
  }
  return std::min(k, 3);
}

int Planes::rangedPlanes() const {
  int n = 0;
  for (const Fundamental& f : linear) n += !f.exact();
  return n;
}

int Planes::dof() const { return 3 - planeRows() + rangedPlanes(); }

Parameter Planes::parameter(int i) const {
  const int free = 3 - planeRows();
  if (i < free) return lengthParameter(free == 1 ? "lambda" : (i == 0 ? "lambda1" : "lambda2"));
  int r = i - free;
  for (const Fundamental& f : linear)
    if (!f.exact() && r-- == 0) return rangeParameter(f);
  return lengthParameter("lambda");
}

void Planes::plan() {
  planned_ = false;
  int k = 0;
  for (std::size_t c = 0; c < linear.size(); ++c) {
    const Fundamental& f = linear[c];
    if (f.point_side != Side::kMobile) return;  // a mobile plane or line turns with R
    const int rows = f.kind == FundamentalKind::kPointPlane  ? 1
                     : f.kind == FundamentalKind::kPointLine ? 2
                     : f.kind == FundamentalKind::kPointPoint ? 3
                                                              : 0;
    for (int r = 0; r < rows && k < 3; ++r) planned_from_[k++] = static_cast<signed char>(c);
  }
  // Every row's height is n·(q − R p) (planeOf, shapeOf): at R = I the rest is R's alone.
  planned_rows_ = planeRowsFor(linear, Matrix3d::Identity());
  planned_ = planned_rows_.k == k;
}

PlaneRows Planes::rowsAt(const Matrix3d& R) const {
  if (!planned_) return planeRowsFor(linear, R);
  PlaneRows rows = planned_rows_;
  for (int i = 0; i < rows.k; ++i) {
    const Fundamental& f = linear[static_cast<std::size_t>(planned_from_[i])];
    rows.h0[i] = rows.n[i].dot(Vector3d(f.q - R * f.p));
  }
  return rows;
}

Vector3d Planes::translation(const Matrix3d& R, const double* t) const {
  const PlaneRows rows = rowsAt(R);
  const int free = 3 - rows.k;
  Vector3d T = planesPoint(rows, t + free);
  for (int j = 0; j < free; ++j) T += t[j] * rows.free[j];
  return T;
}

// The nearest point of the set, then its range values (its heights over the planes) and its free
// coordinates; returns the translation at those parameters.
Vector3d Planes::projectOntoPlanes(const Matrix3d& R, const Vector3d& T, double* t) const {
  const PlaneRows rows = rowsAt(R);
  const Vector3d N = nearestOnRows(rows, linear, T);
  const int free = 3 - rows.k;
  double* v = t + free;
  int r = 0;
  for (const Fundamental& f : linear) {
    if (f.exact()) continue;
    for (int i = 0; i < rows.k; ++i)
      if (rows.ranged[i] == r) {
        const double x = rows.sign[i] * (rows.n[i].dot(N) - rows.h0[i]);
        v[r] = std::min(f.hi, std::max(f.lo, x));
      }
    ++r;
  }
  Vector3d P = planesPoint(rows, v);
  const Vector3d foot = P;
  for (int j = 0; j < free; ++j) {
    t[j] = rows.free[j].dot(T - foot);
    P += t[j] * rows.free[j];
  }
  return P;
}

Vector3d Planes::projectAndPlace(const Matrix3d& R, const Vector3d& T, double* t) const {
  return projectOntoPlanes(R, T, t);
}

void Planes::project(const Matrix3d& R, const Vector3d& T, double* t) const {
  projectOntoPlanes(R, T, t);
}

}  // namespace relpos::manifolds::translation
