#include "local_dof.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <vector>

#include "world_feature.hpp"

namespace relpos::test {
namespace {

using K = FeatureKind;

using W = WorldFeature;

// Smooth residual components of one constraint (zero where it holds). Where a scalar residual
// would have a vanishing gradient at the solution (a zero distance, a zero angle), the vector
// form is used instead (p − q, (p − a) × d, d₁ × d₂).
void residuals(const InputConstraint& c, const Isometry3d& X_WF, const Isometry3d& X_WM,
               std::vector<double>& out) {
  const W F = placeInWorld(c.fixed, X_WF), M = placeInWorld(c.mobile, X_WM);
  const std::string& t = c.type;
  const double v = c.has_value ? c.value : 0.0;
  auto vec = [&](const Vector3d& x) { out.insert(out.end(), {x.x(), x.y(), x.z()}); };
  auto pointLine = [&](const Vector3d& p, const W& l, double dist) {
    Vector3d x = (p - l.a).cross(l.d);
    if (std::abs(dist) < 1e-12)
      vec(x);
    else
      out.push_back(x.norm() - dist);
  };
  auto parallel = [&](const Vector3d& a, const Vector3d& b) { vec(a.cross(b)); };
  // Skew distance: the signed offset along the common normal (smooth where the lines meet).
  auto skew = [&](const W& l1, const W& l2, double dist) {
    const Vector3d n = l1.d.cross(l2.d);
    const double signed_offset = (l2.a - l1.a).dot(n) / n.norm();
    out.push_back(std::abs(dist) < 1e-12 ? signed_offset : std::abs(signed_offset) - dist);
  };
  auto angleRes = [&](const Vector3d& a, const Vector3d& b, double cos_v) {
    if (std::abs(std::abs(cos_v) - 1) < 1e-12)
      parallel(a, b);
    else
      out.push_back(a.dot(b) - cos_v);
  };
  const bool has_point = F.kind == K::kPoint || M.kind == K::kPoint;
  const W& P = M.kind == K::kPoint ? M : F;
  const W& Xo = M.kind == K::kPoint ? F : M;
  const bool lp =
      (F.kind == K::kLine && M.kind == K::kPlane) || (F.kind == K::kPlane && M.kind == K::kLine);
  const W& Ln = F.kind == K::kLine ? F : M;
  const W& Pl = F.kind == K::kPlane ? F : M;
  if (t == "distance" || t == "coincident") {
    const double val = t == "coincident" ? 0.0 : v;
    if (has_point) {
      switch (Xo.kind) {
        case K::kPoint:
          if (std::abs(val) < 1e-12)
            vec(P.a - Xo.a);
          else
            out.push_back((P.a - Xo.a).norm() - val);
          return;
        case K::kLine:
          return pointLine(P.a, Xo, val);
        case K::kCylinder:
          return pointLine(P.a, Xo, Xo.r);
        case K::kPlane:
          out.push_back((P.a - Xo.a).dot(Xo.d) - val);
          return;
      }
    }
    if (F.kind == K::kLine && M.kind == K::kLine) {
      if (!c.parallel) return skew(M, F, val);
      parallel(M.d, F.d);
      return pointLine(M.a, F, val);
    }
    if (lp) {
      out.push_back(Ln.d.dot(Pl.d));
      out.push_back((Ln.a - Pl.a).dot(Pl.d) - val);
      return;
    }
    parallel(M.d, F.d);
    out.push_back((M.a - F.a).dot(F.d) - val);
    return;
  }
  if (t == "angle") return lp ? angleRes(Ln.d, Pl.d, std::sin(v)) : angleRes(M.d, F.d, std::cos(v));
  if (t == "parallel") return lp ? out.push_back(Ln.d.dot(Pl.d)) : parallel(M.d, F.d);
  if (t == "perpendicular") return lp ? parallel(Ln.d, Pl.d) : out.push_back(M.d.dot(F.d));
  if (t == "tangent") {
    if (F.kind == K::kCylinder && M.kind == K::kCylinder) {
      parallel(M.d, F.d);
      out.push_back((M.a - F.a).cross(F.d).norm() - (F.r + M.r));
      return;
    }
    const W& C = F.kind == K::kCylinder ? F : M;
    if (F.kind == K::kLine || M.kind == K::kLine) return skew(C, F.kind == K::kLine ? F : M, C.r);
    const double s = (C.a - Pl.a).dot(Pl.d);
    out.push_back(C.d.dot(Pl.d));
    out.push_back(std::abs(s + C.r) < std::abs(s - C.r) ? s + C.r : s - C.r);
  }
}

}  // namespace

namespace {

// A range constraint, at a pose strictly inside its range, removes no DOF: only its other
// (equality) parts count — a parallelism, a perpendicularity. Those are the rows that do not
// change with the value; `mask` marks them (evaluated once, at X).
std::vector<bool> equalityRows(const InputConstraint& c, const Isometry3d& X_WF,
                               const Isometry3d& X_WM) {
  InputConstraint a = c, b = c;
  a.has_value = b.has_value = true;
  a.value = a.min = a.max = 1.0;
  b.value = b.min = b.max = 2.0;
  std::vector<double> ra, rb;
  residuals(a, X_WF, X_WM, ra);
  residuals(b, X_WF, X_WM, rb);
  std::vector<bool> mask(ra.size());
  for (std::size_t i = 0; i < ra.size(); ++i) mask[i] = std::abs(ra[i] - rb[i]) < 1e-12;
  return mask;
}

bool properRange(const InputConstraint& c) { return c.isRange() && c.min != c.max; }

}  // namespace

int localDof(const Problem& p, const Isometry3d& X) {
  std::vector<std::vector<bool>> masks(p.constraints.size());
  for (std::size_t k = 0; k < p.constraints.size(); ++k)
    if (properRange(p.constraints[k])) masks[k] = equalityRows(p.constraints[k], p.fixed.pose, X);
  auto eval = [&](const Isometry3d& Y) {
    std::vector<double> r;
    for (std::size_t k = 0; k < p.constraints.size(); ++k) {
      const InputConstraint& c = p.constraints[k];
      if (!properRange(c)) {
        residuals(c, p.fixed.pose, Y, r);
        continue;
      }
      InputConstraint a = c;
      a.has_value = true;
      a.value = a.min = a.max = 1.0;
      std::vector<double> ra;
      residuals(a, p.fixed.pose, Y, ra);
      for (std::size_t i = 0; i < ra.size(); ++i)
        if (masks[k][i]) r.push_back(ra[i]);
    }
    return r;
  };
  const std::size_t m = eval(X).size();
  if (m == 0) return 6;
  Eigen::MatrixXd J(m, 6);
  const double h = 1e-6;
  for (int k = 0; k < 6; ++k) {
    Vector3d w = Vector3d::Zero(), v = Vector3d::Zero();
    (k < 3 ? w : v)[k % 3] = h;
    auto moved = [&](double s) {
      Isometry3d D = Isometry3d::Identity();
      if (k < 3) D.linear() = Eigen::AngleAxisd(s * h, w.normalized()).toRotationMatrix();
      Isometry3d Y = X;
      Y.linear() = D.linear() * X.linear();
      Y.translation() = X.translation() + s * v;
      return eval(Y);
    };
    std::vector<double> a = moved(1.0), b = moved(-1.0);
    for (std::size_t i = 0; i < m; ++i) J(i, k) = (a[i] - b[i]) / (2 * h);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J);
  const auto& s = svd.singularValues();
  // Central differences are accurate to ~1e-11 here; near-tangent (but regular) configurations
  // have singular values down to ~1e-5, true dependencies below 1e-9.
  int rank = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s[i] > 1e-8 * std::max(1.0, s[0])) ++rank;
  return 6 - rank;
}

}  // namespace relpos::test
