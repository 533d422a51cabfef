#include "chart.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "rounded_interval.hpp"

namespace relpos::complete::detail {
namespace {

// g for an inequality, g − target for an equation (its residual).
template <typename T>
void evaluateAll(const std::vector<Condition>& cs, const std::array<T, 6>& y, T* out) {
  const LocalPose<T> X(y);
  for (std::size_t i = 0; i < cs.size(); ++i) {
    out[i] = evaluate(cs[i], X);
    if (cs[i].equation()) out[i] = out[i] - lift<T>(cs[i].lo);
  }
}

// y = B·z over a box z.
std::array<FI, 6> boxOfY(const Matrix6d& B, const std::array<FI, 6>& z) {
  std::array<FI, 6> y;
  for (int i = 0; i < 6; ++i) {
    FI s(0.0);
    for (int j = 0; j < 6; ++j) s += z[j] * B(i, j);
    y[i] = s;
  }
  return y;
}

FI intersectOr(const FI& a, const FI& b) {
  const double lo = std::max(a.lower(), b.lower()), hi = std::min(a.upper(), b.upper());
  return lo <= hi ? FI(lo, hi) : a;
}

// Enclosures of the conditions over the y box `yb` (z the box in the basis' coordinates): the
// naive one met with the mean-value form about y = 0 (its gradient over the box).
void enclose(const std::vector<Condition>& cs, const Matrix6d& B, const std::array<FI, 6>& z,
             const std::array<FI, 6>& yb, std::vector<FI>* value,
             std::vector<std::array<FI, 6>>* jacobian) {
  const std::size_t n = cs.size();
  std::vector<FI> at0(n);
  std::array<Dual<FI>, 6> yd;
  for (int i = 0; i < 6; ++i) yd[i] = Dual<FI>::variable(yb[i], i);
  std::vector<Dual<FI>> dual(n);
  evaluateAll(cs, yd, dual.data());
  std::array<FI, 6> zero;
  zero.fill(FI(0.0));
  evaluateAll(cs, zero, at0.data());
  value->resize(n);
  jacobian->resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    (*jacobian)[i] = dual[i].g;
    FI mv = at0[i];
    for (int j = 0; j < 6; ++j) {
      FI gj(0.0);  // ∂g/∂z_j = Σ_k ∂g/∂y_k B(k, j)
      for (int k = 0; k < 6; ++k) gj += dual[i].g[k] * B(k, j);
      mv += gj * z[j];
    }
    (*value)[i] = intersectOr(dual[i].v, mv);
  }
}

bool inside(const FI& v, double lo, double hi) { return lo <= v.lower() && v.upper() <= hi; }

}  // namespace

void equationsAt(const std::vector<Condition>& eqs, const Vector6d& y, EquationVector* e,
                 EquationJacobian* J) {
  const auto m = static_cast<Eigen::Index>(eqs.size());
  e->resize(m);
  if (!J) {
    std::array<double, 6> ya;
    for (int i = 0; i < 6; ++i) ya[i] = y[i];
    evaluateAll(eqs, ya, e->data());
    return;
  }
  std::array<Dual<double>, 6> yd;
  for (int i = 0; i < 6; ++i) yd[i] = Dual<double>::variable(y[i], i);
  std::array<Dual<double>, 6> out;
  evaluateAll(eqs, yd, out.data());
  J->resize(m, 6);
  for (Eigen::Index i = 0; i < m; ++i) {
    (*e)[i] = out[static_cast<std::size_t>(i)].v;
    for (int j = 0; j < 6; ++j) (*J)(i, j) = out[static_cast<std::size_t>(i)].g[j];
  }
}

void poseAt(const Matrix3d& R0, const Vector3d& t0, const Vector6d& y, Matrix3d* R, Vector3d* t) {
  std::array<double, 6> ya;
  for (int i = 0; i < 6; ++i) ya[i] = y[i];
  const LocalPose<double> X(ya);
  Matrix3d Q;
  for (int i = 0; i < 9; ++i) Q(i / 3, i % 3) = X.Q[i];
  *R = R0 * Q;
  *t = t0 + R0 * Vector3d(y[3], y[4], y[5]);
}

bool makeChart(const ConditionSystem& system, const Matrix3d& R0, const Vector3d& t0, Chart* out) {
  Chart c;
  c.R0 = R0, c.t0 = t0;
  for (const Condition& e : system.equations) c.equations.push_back(inBaseFrame(e, R0, t0));
  for (const Condition& e : system.inequalities) c.inequalities.push_back(inBaseFrame(e, R0, t0));
  c.m = static_cast<int>(c.equations.size());
  if (c.m > 6) return false;
  c.d = 6 - c.m;
  std::vector<double> g(c.inequalities.size());
  evaluateAll(c.inequalities, std::array<double, 6>{}, g.data());
  for (std::size_t i = 0; i < g.size(); ++i)
    if (!(c.inequalities[i].lo < g[i] && g[i] < c.inequalities[i].hi)) return false;
  if (c.m > 0) {
    EquationVector e;
    EquationJacobian J;
    equationsAt(c.equations, Vector6d::Zero(), &e, &J);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    if (!(s[c.m - 1] > kRankGap * std::max(1.0, s[0]))) return false;
    const Matrix6d V = svd.matrixV();
    // tangent first (the null space), normal last
    c.basis.leftCols(c.d) = V.rightCols(c.d);
    c.basis.rightCols(c.m) = V.leftCols(c.m);
    const EquationMatrix Js = J * c.basis.rightCols(c.m);
    c.Y.topLeftCorner(c.m, c.m) = Js.inverse();
  }
  *out = std::move(c);
  return true;
}

bool certifyChart(const Chart& c, const std::array<double, 6>& radius, double* slice) {
  RoundUp rounding;
  std::array<FI, 6> z;
  for (int j = 0; j < 6; ++j) z[j] = j < c.d ? FI(-radius[j], radius[j]) : FI(0.0);
  std::vector<FI> value;
  std::vector<std::array<FI, 6>> jac;
  double sigma = 0.0;
  if (c.m > 0) {
    enclose(c.equations, c.basis, z, boxOfY(c.basis, z), &value, &jac);
    std::vector<FI> ye(static_cast<std::size_t>(c.m));  // Y·E over Θ × {0}
    double big = 0.0;
    for (int i = 0; i < c.m; ++i) {
      FI s(0.0);
      for (int k = 0; k < c.m; ++k) s += value[static_cast<std::size_t>(k)] * c.Y(i, k);
      ye[static_cast<std::size_t>(i)] = s;
      big = std::max(big, mag(s));
    }
    sigma = std::max(2.0 * big, 1e-13);
    bool proven = false;
    for (int attempt = 0; attempt < 8 && !proven; ++attempt) {
      if (!(sigma < 0.5)) return false;
      for (int j = c.d; j < 6; ++j) z[j] = FI(-sigma, sigma);
      enclose(c.equations, c.basis, z, boxOfY(c.basis, z), &value, &jac);
      // J_s = J_y·B_normal over the box
      std::array<std::array<FI, 6>, 6> js;
      for (int r = 0; r < c.m; ++r)
        for (int l = 0; l < c.m; ++l) {
          FI sum(0.0);
          for (int q = 0; q < 6; ++q)
            sum += jac[static_cast<std::size_t>(r)][q] * c.basis(q, c.d + l);
          js[r][l] = sum;
        }
      proven = true;
      double needed = 0.0;
      for (int i = 0; i < c.m; ++i) {
        FI k = -ye[static_cast<std::size_t>(i)];
        double rho = 0.0;  // the row's contraction: Σ_l |I − Y·J_s|(i, l)
        for (int l = 0; l < c.m; ++l) {
          FI yjs(0.0);  // (Y·J_s)(i, l)
          for (int r = 0; r < c.m; ++r) yjs += js[r][l] * c.Y(i, r);
          const FI mil = FI(i == l ? 1.0 : 0.0) - yjs;
          rho += mag(mil);
          k += mil * FI(-sigma, sigma);
        }
        if (!(-sigma < k.lower() && k.upper() < sigma)) proven = false;
        // No contraction on this slice: none on a wider one (J_s only spreads), so no slice
        // proves this box — the growth's failed boxes end here, not after eight slices.
        if (!(rho < 1.0)) return false;
        // the slice the row would need if the contraction stayed: |Y·E| / (1 − ρ)
        needed = std::max(needed, mag(ye[static_cast<std::size_t>(i)]) / (1.0 - rho));
      }
      if (!proven) sigma = std::max(1.25 * needed, 1.5 * sigma);
    }
    if (!proven) return false;
  }
  if (!c.inequalities.empty()) {
    enclose(c.inequalities, c.basis, z, boxOfY(c.basis, z), &value, &jac);
    for (std::size_t i = 0; i < c.inequalities.size(); ++i)
      if (!inside(value[i], c.inequalities[i].lo, c.inequalities[i].hi)) return false;
  }
  *slice = sigma;
  return true;
}

bool holdAtExactBase(const Chart& c, const std::vector<Condition>& extra,
                     const std::vector<double>& tolerance, std::vector<double>* proven) {
  double sigma = 0.0;
  if (!certifyChart(c, std::array<double, 6>{}, &sigma)) return false;
  std::vector<Condition> local;
  inBaseFrame(extra, c.R0, c.t0, &local);
  RoundUp rounding;
  std::array<FI, 6> z;
  for (int j = 0; j < 6; ++j) z[j] = j < c.d ? FI(0.0) : FI(-sigma, sigma);
  std::vector<FI> value;
  std::vector<std::array<FI, 6>> jac;
  enclose(local, c.basis, z, boxOfY(c.basis, z), &value, &jac);
  // an equation's enclosure is of its residual g − value (evaluateAll)
  for (std::size_t i = 0; i < local.size(); ++i) {
    const double lo = local[i].equation() ? 0.0 : local[i].lo;
    const double hi = local[i].equation() ? 0.0 : local[i].hi;
    if (!inside(value[i], lo - tolerance[i], hi + tolerance[i])) return false;
  }
  if (proven) {
    proven->clear();
    for (const FI& v : value) proven->push_back(mag(v));
  }
  return true;
}

bool growChart(Chart& c, double start, double limit, bool each_axis) {
  std::array<double, 6> r{};
  for (int j = 0; j < c.d; ++j) r[j] = start;
  double sigma = 0.0;
  if (!certifyChart(c, r, &sigma)) return false;
  c.radius = r;
  c.slice = sigma;
  if (c.d == 0) return true;  // an isolated pose: nothing to grow
  auto tryBox = [&](const std::array<double, 6>& box) {
    double s = 0.0;
    if (!certifyChart(c, box, &s)) return false;
    r = box, sigma = s;
    return true;
  };
  // Every tangent coordinate alike, by eights while the proof holds, then twice halving the
  // factor (in logarithm) between the last box proven and the first not: about six proofs
  // where doubling took a dozen (each costs as much as the next). Then each coordinate alone,
  // doubled while it holds (a slide may reach far, a turn not).
  auto scaled = [&](double f) {
    std::array<double, 6> box = r;
    for (int j = 0; j < c.d; ++j) box[j] *= f;
    return box;
  };
  double factor = 8.0;
  while (r[0] * factor <= limit && tryBox(scaled(factor))) {
  }
  for (int k = 0; k < 2; ++k) {
    factor = std::sqrt(factor);
    if (r[0] * factor <= limit) tryBox(scaled(factor));
  }
  for (int j = 0; j < c.d && each_axis; ++j)
    while (r[j] * 2.0 <= limit) {
      std::array<double, 6> box = r;
      box[j] *= 2.0;
      if (!tryBox(box)) break;
    }
  c.radius = r;
  c.slice = sigma;
  return true;
}

Vector6d localCoordinates(const Chart& c, const Matrix3d& R, const Vector3d& t) {
  const Eigen::Quaterniond q(Matrix3d(c.R0.transpose() * R));
  const double w = std::max(std::abs(q.w()), 1e-6);
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  Vector6d y;
  y << sign * q.x() / w, sign * q.y() / w, sign * q.z() / w, c.R0.transpose() * (t - c.t0);
  return y;
}

std::array<double, 6> chartProject(const Chart& c, const Matrix3d& R, const Vector3d& t) {
  const Vector6d z = c.basis.transpose() * localCoordinates(c, R, t);
  std::array<double, 6> theta{};
  for (int j = 0; j < c.d; ++j) theta[j] = std::clamp(z[j], -c.radius[j], c.radius[j]);
  return theta;
}

void chartPose(const Chart& c, const std::array<double, 6>& theta, Matrix3d* R, Vector3d* t) {
  Vector6d z = Vector6d::Zero();
  for (int j = 0; j < c.d; ++j) z[j] = theta[j];
  if (c.m > 0) {
    const EquationMatrix Y = c.Y.topLeftCorner(c.m, c.m);
    EquationVector e, step;
    // the simplified step contracts on the slice (Krawczyk's test); Newton for the last digits
    // only where it has not converged (its Jacobian costs several evaluations of the equations)
    bool converged = false;
    for (int it = 0; it < 60 && !converged; ++it) {
      equationsAt(c.equations, c.basis * z, &e);
      step = Y * e;
      z.tail(c.m) -= step;
      converged = step.lpNorm<Eigen::Infinity>() < 1e-15;
    }
    for (int it = 0; it < 2 && !converged; ++it) {
      EquationJacobian J;
      equationsAt(c.equations, c.basis * z, &e, &J);
      const EquationMatrix Js = J * c.basis.rightCols(c.m);
      step = Js.partialPivLu().solve(e);
      if (!step.allFinite() || step.lpNorm<Eigen::Infinity>() > c.slice) break;
      z.tail(c.m) -= step;
    }
  }
  poseAt(c.R0, c.t0, c.basis * z, R, t);
}

}  // namespace relpos::complete::detail
