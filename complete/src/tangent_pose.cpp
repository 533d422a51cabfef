#include "tangent_pose.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "chart.hpp"
#include "rounded_interval.hpp"

namespace relpos::complete::detail {
namespace {

// A condition's residual (g − target for an equation), gradient and Hessian at y, a point or a
// box: forward derivatives of forward derivatives.
template <typename S>
struct Taylor2 {
  S v;
  std::array<S, 6> g;
  std::array<std::array<S, 6>, 6> h;
};

template <typename S>
Taylor2<S> taylor(const Condition& c, const std::array<S, 6>& y) {
  using T = Dual<Dual<S>>;
  std::array<T, 6> yd;
  for (int i = 0; i < 6; ++i) {
    T d(Dual<S>::variable(y[i], i));
    d.g[i] = Dual<S>(S(1.0));
    yd[i] = d;
  }
  const LocalPose<T> X(yd);
  T r = evaluate(c, X);
  if (c.equation()) r = r - lift<T>(c.lo);
  Taylor2<S> out;
  out.v = r.v.v;
  for (int i = 0; i < 6; ++i) {
    out.g[i] = r.v.g[i];
    for (int j = 0; j < 6; ++j) out.h[i][j] = r.g[i].g[j];
  }
  return out;
}

// The critical points of g on the set of h: unknowns X = (y, λ), equations h(y) = 0 and
// ∇g(y) − Σ λ_a ∇h_a(y) = 0.
struct Lagrange {
  std::vector<Condition> h;
  Condition g;
  int n() const { return 6 + static_cast<int>(h.size()); }
};

// F(X) and its Jacobian, S a scalar (double, or FI over a box of X).
template <typename S>
void lagrange(const Lagrange& L, const std::vector<S>& X, std::vector<S>* F,
              std::vector<std::vector<S>>* J) {
  const int r = static_cast<int>(L.h.size()), n = L.n();
  std::array<S, 6> y;
  for (int i = 0; i < 6; ++i) y[i] = X[static_cast<std::size_t>(i)];
  F->assign(static_cast<std::size_t>(n), S(0.0));
  J->assign(static_cast<std::size_t>(n), std::vector<S>(static_cast<std::size_t>(n), S(0.0)));
  const Taylor2<S> g = taylor(L.g, y);
  for (int k = 0; k < 6; ++k) {
    (*F)[static_cast<std::size_t>(r + k)] = g.g[k];
    for (int j = 0; j < 6; ++j)
      (*J)[static_cast<std::size_t>(r + k)][static_cast<std::size_t>(j)] = g.h[k][j];
  }
  for (int a = 0; a < r; ++a) {
    const Taylor2<S> h = taylor(L.h[static_cast<std::size_t>(a)], y);
    const S lambda = X[static_cast<std::size_t>(6 + a)];
    (*F)[static_cast<std::size_t>(a)] = h.v;
    for (int j = 0; j < 6; ++j)
      (*J)[static_cast<std::size_t>(a)][static_cast<std::size_t>(j)] = h.g[j];
    for (int k = 0; k < 6; ++k) {
      auto& row = (*J)[static_cast<std::size_t>(r + k)];
      (*F)[static_cast<std::size_t>(r + k)] -= lambda * h.g[k];
      for (int j = 0; j < 6; ++j) row[static_cast<std::size_t>(j)] -= lambda * h.h[k][j];
      row[static_cast<std::size_t>(6 + a)] = -h.g[k];
    }
  }
}

Eigen::MatrixXd toMatrix(const std::vector<std::vector<double>>& J) {
  Eigen::MatrixXd M(J.size(), J.size());
  for (std::size_t i = 0; i < J.size(); ++i)
    for (std::size_t j = 0; j < J.size(); ++j)
      M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = J[i][j];
  return M;
}

// Newton's method on the Lagrange system from X; false when it does not settle near the start.
bool newton(const Lagrange& L, Eigen::VectorXd* X) {
  std::vector<double> x(X->data(), X->data() + X->size()), F;
  std::vector<std::vector<double>> J;
  for (int it = 0; it < 40; ++it) {
    lagrange(L, x, &F, &J);
    const Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(F.data(), L.n());
    const Eigen::VectorXd step = toMatrix(J).partialPivLu().solve(f);
    if (!step.allFinite()) return false;
    for (int i = 0; i < L.n(); ++i) x[static_cast<std::size_t>(i)] -= step[i];
    if (step.lpNorm<Eigen::Infinity>() <
        1e-15 * (1.0 + Eigen::Map<Eigen::VectorXd>(x.data(), L.n()).lpNorm<Eigen::Infinity>()))
      break;
  }
  *X = Eigen::Map<Eigen::VectorXd>(x.data(), L.n());
  // still local: the pose within a small turn and slide of the start
  return X->allFinite() && X->head<6>().lpNorm<Eigen::Infinity>() < 0.1;
}

// Krawczyk's test of the Lagrange system on the box X ± δ(1 + |X|) (Y ≈ the inverse of its
// Jacobian at X).
bool krawczyk(const Lagrange& L, const Eigen::VectorXd& X, const Eigen::MatrixXd& Y, double delta) {
  RoundUp rounding;
  const int n = L.n();
  std::vector<FI> point(static_cast<std::size_t>(n)), box(static_cast<std::size_t>(n)), F, Fb;
  std::vector<double> width(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    width[u] = delta * (1.0 + std::abs(X[i]));
    point[u] = FI(X[i]);
    box[u] = FI(X[i]) + FI(-width[u], width[u]);
  }
  std::vector<std::vector<FI>> Jp, J;
  lagrange(L, point, &F, &Jp);
  lagrange(L, box, &Fb, &J);
  for (int i = 0; i < n; ++i) {
    FI k(0.0);
    for (int l = 0; l < n; ++l) {
      k -= FI(Y(i, l)) * F[static_cast<std::size_t>(l)];
      FI m(i == l ? 1.0 : 0.0);
      for (int q = 0; q < n; ++q)
        m -= FI(Y(i, q)) * J[static_cast<std::size_t>(q)][static_cast<std::size_t>(l)];
      k += m * FI(-width[static_cast<std::size_t>(l)], width[static_cast<std::size_t>(l)]);
    }
    // K − X within the box's half-width, strictly
    const double w = width[static_cast<std::size_t>(i)];
    if (!(-w < k.lower() && k.upper() < w)) return false;
  }
  return true;
}

// Whether g's Hessian on the set of h (the Lagrangian's, on the tangent space of h = 0) is
// definite at X: an extremum of g there, the set g = its value near it that pose alone.
bool definite(const Lagrange& L, const Eigen::VectorXd& X) {
  const int r = static_cast<int>(L.h.size());
  std::vector<double> x(X.data(), X.data() + X.size()), F;
  std::vector<std::vector<double>> J;
  lagrange(L, x, &F, &J);
  const Eigen::MatrixXd M = toMatrix(J);
  const Eigen::MatrixXd H = M.block(r, 0, 6, 6);        // ∇²g − Σ λ ∇²h
  Eigen::MatrixXd N = Eigen::MatrixXd::Identity(6, 6);  // the tangent space of h = 0
  if (r > 0) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(M.block(0, 0, r, 6), Eigen::ComputeFullV);
    N = svd.matrixV().rightCols(6 - r);
  }
  const Eigen::MatrixXd P = N.transpose() * (0.5 * (H + H.transpose())) * N;
  const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues();
  const double big = e.cwiseAbs().maxCoeff();
  if (!(big > 0.0)) return false;
  const bool positive = e.minCoeff() > 1e-6 * big, negative = e.maxCoeff() < -1e-6 * big;
  return positive || negative;
}

bool inside(const FI& v, double lo, double hi) { return lo <= v.lower() && v.upper() <= hi; }

}  // namespace

bool tangentPose(const ConditionSystem& system, const std::vector<Condition>& implied,
                 const Matrix3d& R0, const Vector3d& t0, double length_tol, double angle_tol,
                 TangentPose* out) {
  std::vector<Condition> eqs, ins;
  inBaseFrame(system.equations, R0, t0, &eqs);
  inBaseFrame(system.inequalities, R0, t0, &ins);
  const auto m = static_cast<Eigen::Index>(eqs.size());
  if (m < 2 || m > 6) return false;
  // the rank short by one at the start: one combination of the gradients nearly vanishes
  Eigen::MatrixXd G(m, 6);
  const std::array<double, 6> zero{};
  for (Eigen::Index i = 0; i < m; ++i) {
    const Taylor2<double> t = taylor(eqs[static_cast<std::size_t>(i)], zero);
    for (int j = 0; j < 6; ++j) G(i, j) = t.g[j];
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullU);
  const Eigen::VectorXd s = svd.singularValues();
  if (!(s[0] > 0.0) || !(s[m - 1] < 1e-4 * s[0]) || (m >= 2 && !(s[m - 2] > 1e-3 * s[0])))
    return false;
  // g: the equation with the most weight in that combination; h the others
  Eigen::Index gi = 0;
  svd.matrixU().col(m - 1).cwiseAbs().maxCoeff(&gi);
  Lagrange L;
  for (Eigen::Index i = 0; i < m; ++i) {
    const Condition& c = eqs[static_cast<std::size_t>(i)];
    if (i == gi)
      L.g = c;
    else
      L.h.push_back(c);
  }
  const int r = static_cast<int>(L.h.size()), n = L.n();
  // λ: ∇g = Σ λ ∇h in the least-squares sense at the start
  Eigen::MatrixXd Gh(6, r);
  Eigen::VectorXd gg(6);
  for (int k = 0; k < 6; ++k) gg[k] = G(gi, k);
  for (int a = 0, i = 0; i < m; ++i)
    if (i != gi) Gh.col(a++) = G.row(i).transpose();
  Eigen::VectorXd X = Eigen::VectorXd::Zero(n);
  X.tail(r) = Gh.colPivHouseholderQr().solve(gg);
  if (!newton(L, &X) || !definite(L, X)) return false;
  std::vector<double> x(X.data(), X.data() + n), F;
  std::vector<std::vector<double>> J;
  lagrange(L, x, &F, &J);
  const Eigen::MatrixXd Y = toMatrix(J).inverse();
  if (!Y.allFinite()) return false;
  double delta = 0.0;
  for (double d = 1e-11; d <= 1e-5 && delta == 0.0; d *= 10.0)
    if (krawczyk(L, X, Y, d)) delta = d;
  if (delta == 0.0) return false;
  Vector6d yv;
  for (int i = 0; i < 6; ++i) yv[i] = X[i];
  poseAt(R0, t0, yv, &out->R, &out->t);
  // Over the pose's part of the box: g and every h within half its tolerance (h holds exactly
  // at the critical point, somewhere in the box), the implied equations within theirs, every
  // inequality in its range — each equation's allowance in its own units at the pose's turn
  // (a skew distance's by the sine of its lines' angle there).
  {
    std::vector<Condition> implied_here;
    inBaseFrame(implied, R0, t0, &implied_here);
    std::vector<double> allowed;
    for (const Condition& c : system.equations)
      allowed.push_back(toleranceAt(c, out->R, 0.5 * length_tol, 0.5 * angle_tol));
    for (const Condition& c : implied)
      allowed.push_back(toleranceAt(c, out->R, length_tol, angle_tol));
    RoundUp rounding;
    std::array<FI, 6> y;
    for (int i = 0; i < 6; ++i)
      y[i] = FI(X[i]) + FI(-delta * (1.0 + std::abs(X[i])), delta * (1.0 + std::abs(X[i])));
    const LocalPose<FI> P(y);
    std::size_t k = 0;
    for (const std::vector<Condition>* list : {&eqs, &implied_here})
      for (const Condition& c : *list) {
        const FI off = evaluate(c, P) - FI(c.lo);
        if (!inside(off, -allowed[k], allowed[k])) return false;
        ++k;
      }
    for (const Condition& c : ins)
      if (!inside(evaluate(c, P), c.lo, c.hi)) return false;
  }
  out->radius = 0.0;
  for (int i = 0; i < 6; ++i) out->radius = std::max(out->radius, delta * (1.0 + std::abs(X[i])));
  return true;
}

}  // namespace relpos::complete::detail
