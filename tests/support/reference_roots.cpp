#include "reference_roots.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "evaluator.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::test {
namespace {

using VectorXd = Eigen::VectorXd;
using MatrixXd = Eigen::MatrixXd;

// The problem's length: the span of its fixed and mobile features (points and support points)
// and its largest length value, so rotation coordinates (times this) and translations weigh alike.
double lengthOf(const Problem& p) {
  double s = 1e-3;
  for (const InputConstraint& c : p.constraints) {
    s = std::max({s, c.fixed.point.norm(), c.mobile.point.norm()});
    if (c.has_value && c.type == "distance") s = std::max(s, std::abs(c.value));
  }
  return s;
}

// The pose moved by local coordinates x = (L ω, δt): R ← exp(ω) R, t ← t + δt.
Isometry3d moved(const Isometry3d& X, const double* x, double L) {
  Isometry3d Y = X;
  const Vector3d w(x[0] / L, x[1] / L, x[2] / L);
  if (w.norm() > 0) Y.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()) * X.linear();
  Y.translation() += Vector3d(x[3], x[4], x[5]);
  return Y;
}

bool residuals(const Problem& p, const Isometry3d& X, VectorXd* r) {
  r->resize(static_cast<Eigen::Index>(p.constraints.size()));
  for (std::size_t i = 0; i < p.constraints.size(); ++i)
    if (!signedResidual(p.constraints[i], p.fixed.pose, X, &(*r)[static_cast<Eigen::Index>(i)]))
      return false;
  return r->allFinite();
}

// Central differences in the six local coordinates: the residuals are smooth away from the
// singular values (a zero distance), which 0-DOF benchmarks avoid.
bool jacobian(const Problem& p, const Isometry3d& X, double L, MatrixXd* J) {
  const Eigen::Index m = static_cast<Eigen::Index>(p.constraints.size());
  J->resize(m, 6);
  const double h = 1e-7 * L;
  VectorXd rp, rm;
  for (int k = 0; k < 6; ++k) {
    double x[6] = {0, 0, 0, 0, 0, 0};
    x[k] = h;
    if (!residuals(p, moved(X, x, L), &rp)) return false;
    x[k] = -h;
    if (!residuals(p, moved(X, x, L), &rm)) return false;
    J->col(k) = (rp - rm) / (2 * h);
  }
  return true;
}

Isometry3d randomPose(std::mt19937_64& g, const Vector3d& centre, double half) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-half, half);
  Quaterniond q(n(g), n(g), n(g), n(g));  // uniform on SO(3) once normalised
  q.normalize();
  Isometry3d X = Isometry3d::Identity();
  X.linear() = q.toRotationMatrix();
  X.translation() = centre + Vector3d(u(g), u(g), u(g));
  return X;
}

}  // namespace

bool newtonSolve(const Problem& p, const Isometry3d& X0, const ReferenceOptions& o, Isometry3d* X) {
  const double L = lengthOf(p);
  Isometry3d Y = X0;
  VectorXd r;
  MatrixXd J;
  if (!residuals(p, Y, &r)) return false;
  double lambda = 1e-3, cost = r.squaredNorm();
  for (int it = 0; it < o.max_iterations && cost > 1e-30 * L * L; ++it) {
    if (!jacobian(p, Y, L, &J)) return false;
    const MatrixXd A = J.transpose() * J;
    const VectorXd b = -J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      MatrixXd D = A;
      D.diagonal().array() += lambda * (1.0 + A.diagonal().array());
      const VectorXd dx = D.ldlt().solve(b);
      if (!dx.allFinite()) return false;
      const Isometry3d Z = moved(Y, dx.data(), L);
      VectorXd rz;
      if (residuals(p, Z, &rz) && rz.squaredNorm() < cost) {
        Y = Z;
        r = rz;
        cost = rz.squaredNorm();
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) break;  // a local minimum of the cost (not a root), or converged
  }
  // A few Gauss-Newton steps with the minimum-norm solution polish a converged root (and move
  // along nothing when the set is not isolated).
  for (int it = 0; it < 3; ++it) {
    if (!jacobian(p, Y, L, &J)) return false;
    const VectorXd dx = J.completeOrthogonalDecomposition().solve(-r);
    if (!dx.allFinite()) break;
    const Isometry3d Z = moved(Y, dx.data(), L);
    VectorXd rz;
    if (!residuals(p, Z, &rz) || rz.squaredNorm() >= r.squaredNorm()) break;
    Y = Z;
    r = rz;
  }
  if (worstViolation(p, Y) > o.verify_tolerance) return false;
  *X = Y;
  return true;
}

WorldLine undirectedLine(const Problem& p, const Isometry3d& X) {
  const Feature* line = nullptr;
  for (const InputConstraint& c : p.constraints)
    if (c.mobile.kind == FeatureKind::kLine) line = &c.mobile;
  WorldLine w{Vector3d::Zero(), Vector3d::UnitZ()};
  if (!line) return w;
  const Feature f = line->placed(X);
  Vector3d d = f.direction.normalized();
  Eigen::Index k;
  d.cwiseAbs().maxCoeff(&k);
  if (d[k] < 0) d = -d;
  w.direction = d;
  w.foot = f.point - f.point.dot(d) * d;
  return w;
}

double lineDistance(const WorldLine& a, const WorldLine& b) {
  return (a.foot - b.foot).norm() + (a.direction - b.direction).norm();
}

double jacobianConditioning(const Problem& p, const Isometry3d& X, int* rank) {
  MatrixXd J;
  if (!jacobian(p, X, lengthOf(p), &J)) return 0.0;
  const VectorXd s = Eigen::JacobiSVD<MatrixXd>(J).singularValues();
  if (rank) *rank = static_cast<int>((s.array() > 1e-8 * s[0]).count());
  return s.size() ? s[s.size() - 1] / s[0] : 0.0;
}

ReferenceRoots referenceRoots(const Problem& p, const ReferenceOptions& o) {
  ReferenceRoots out;
  // Initial translations in a box about the fixed features' centre, wide enough that every pose
  // holding the constraints is inside: the features' span plus the largest value.
  Vector3d centre = Vector3d::Zero();
  for (const InputConstraint& c : p.constraints) centre += p.fixed.pose * c.fixed.point;
  centre /= std::max<double>(1.0, static_cast<double>(p.constraints.size()));
  const double half = 2.0 * lengthOf(p);
  std::mt19937_64 g(o.seed);
  std::vector<WorldLine> lines;
  for (int s = 0; s < o.starts; ++s) {
    ++out.starts;
    Isometry3d X;
    if (!newtonSolve(p, randomPose(g, centre, half), o, &X)) continue;
    ++out.converged;
    std::size_t found = out.poses.size();
    const WorldLine wl = o.line_quotient ? undirectedLine(p, X) : WorldLine{};
    for (std::size_t i = 0; i < out.poses.size() && found == out.poses.size(); ++i) {
      const double d = o.line_quotient ? lineDistance(wl, lines[i]) : poseDistance(X, out.poses[i]);
      if (d < o.duplicate_distance) found = i;
    }
    if (found == out.poses.size()) {
      out.poses.push_back(X);
      out.hits.push_back(0);
      lines.push_back(wl);
    }
    ++out.hits[found];
  }
  return out;
}

}  // namespace relpos::test
