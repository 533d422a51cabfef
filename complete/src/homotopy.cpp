#include "homotopy.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "random.hpp"

namespace relpos::complete::detail {
namespace {

bool finite(const CVec& x) {
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i].real()) || !std::isfinite(x[i].imag())) return false;
  return true;
}

}  // namespace

void CoefficientPolynomials::evaluate(Complex tau, Complex* c, Complex* dc) const {
  // Horner for the value and the derivative together, on raw doubles (see evaluate()).
  const int m = degree + 1;
  const double tr = tau.real(), ti = tau.imag();
  const double* av = reinterpret_cast<const double*>(a.data());
  double* cv = reinterpret_cast<double*>(c);
  double* dv = reinterpret_cast<double*>(dc);
  for (int t = 0; t < terms; ++t) {
    const double* at = av + 2 * static_cast<std::size_t>(t) * m;
    double vr = at[2 * degree], vi = at[2 * degree + 1], dr = 0.0, di = 0.0;
    for (int j = degree - 1; j >= 0; --j) {
      const double ndr = dr * tr - di * ti + vr, ndi = dr * ti + di * tr + vi;
      dr = ndr;
      di = ndi;
      const double nvr = vr * tr - vi * ti + at[2 * j], nvi = vr * ti + vi * tr + at[2 * j + 1];
      vr = nvr;
      vi = nvi;
    }
    cv[2 * t] = vr;
    cv[2 * t + 1] = vi;
    if (dc) {
      dv[2 * t] = dr;
      dv[2 * t + 1] = di;
    }
  }
}

namespace {

// Value and derivative of every term's polynomial at real s (Horner), degree D known at compile
// time for the common degrees (the inner loop unrolled), or d at run time (D < 0).
template <int D>
void hornerReal(const double* a, int terms, int d, double s, double* c, double* dc) {
  const int degree = D >= 0 ? D : d;
  for (int t = 0; t < terms; ++t) {
    const double* at = a + 2 * static_cast<std::size_t>(t) * (degree + 1);
    Pair v = loadPair(at + 2 * degree), dv{0.0, 0.0};
    for (int j = degree - 1; j >= 0; --j) {
      dv = dv * s + v;
      v = v * s + loadPair(at + 2 * j);
    }
    storePair(c + 2 * t, v);
    storePair(dc + 2 * t, dv);
  }
}

}  // namespace

void CoefficientPolynomials::evaluate(double s, Complex* c, Complex* dc) const {
  const double* av = reinterpret_cast<const double*>(a.data());
  double* cv = reinterpret_cast<double*>(c);
  double* dv = reinterpret_cast<double*>(dc);
  switch (degree) {
    case 1:
      return hornerReal<1>(av, terms, degree, s, cv, dv);
    case 2:
      return hornerReal<2>(av, terms, degree, s, cv, dv);
    case 3:
      return hornerReal<3>(av, terms, degree, s, cv, dv);
    default:
      return hornerReal<-1>(av, terms, degree, s, cv, dv);
  }
}

CoefficientPolynomials alongArc(const CoefficientPolynomials& p, Complex gamma) {
  // D^d c(τ(s)) = Σ_j a_j γ^j s^j (1 + δ s)^(d − j), δ = γ − 1: s^k takes a_j γ^j C(d − j, k − j)
  // δ^(k − j) from each j ≤ k.
  const int d = p.degree, m = d + 1;
  const Complex delta = gamma - 1.0;
  std::vector<Complex> w(static_cast<std::size_t>(m) * m, Complex(0.0, 0.0));  // w[j m + k]
  Complex gj(1.0, 0.0);
  for (int j = 0; j <= d; ++j) {
    Complex term = gj;  // γ^j C(d − j, i) δ^i for i = k − j
    for (int i = 0; j + i <= d; ++i) {
      w[static_cast<std::size_t>(j) * m + j + i] = term;
      term *= delta * double(d - j - i) / double(i + 1);
    }
    gj *= gamma;
  }
  CoefficientPolynomials out;
  out.terms = p.terms;
  out.degree = d;
  out.a.assign(p.a.size(), Complex(0.0, 0.0));
  for (int t = 0; t < p.terms; ++t)
    for (int j = 0; j <= d; ++j)
      for (int k = j; k <= d; ++k)
        out.a[static_cast<std::size_t>(t) * m + k] +=
            p.a[static_cast<std::size_t>(t) * m + j] * w[static_cast<std::size_t>(j) * m + k];
  return out;
}

CoefficientPolynomials interpolateSegment(const Family& f, const Complex* p0, const Complex* p1) {
  CoefficientPolynomials out;
  out.terms = static_cast<int>(f.shape().terms.size());
  out.degree = std::max(0, f.coefficientDegree());
  const int m = out.degree + 1;
  const int np = f.parameterCount();
  // Values at τ_k = k / degree, then the inverse Vandermonde matrix gives the monomial basis.
  Eigen::MatrixXd V(m, m);
  for (int k = 0; k < m; ++k) {
    const double tk = out.degree == 0 ? 0.0 : double(k) / out.degree;
    for (int j = 0; j < m; ++j) V(k, j) = std::pow(tk, j);
  }
  const Eigen::MatrixXd Vinv = V.inverse();
  std::vector<Complex> params(np), values(static_cast<std::size_t>(m) * out.terms);
  for (int k = 0; k < m; ++k) {
    const double tk = out.degree == 0 ? 0.0 : double(k) / out.degree;
    for (int i = 0; i < np; ++i) params[i] = p0[i] + tk * (p1[i] - p0[i]);
    f.coefficients(params.data(), values.data() + static_cast<std::size_t>(k) * out.terms);
  }
  out.a.assign(static_cast<std::size_t>(m) * out.terms, Complex(0.0, 0.0));
  for (int t = 0; t < out.terms; ++t)
    for (int j = 0; j < m; ++j) {
      Complex s(0.0, 0.0);
      for (int k = 0; k < m; ++k)
        s += Vinv(j, k) * values[static_cast<std::size_t>(k) * out.terms + t];
      out.a[static_cast<std::size_t>(t) * m + j] = s;
    }
  return out;
}

Complex Arc::tau(double s) const { return gamma * s / (1.0 + (gamma - 1.0) * s); }

Complex Arc::dtau(double s) const {
  const Complex d = 1.0 + (gamma - 1.0) * s;
  return gamma / (d * d);
}

Complex randomGamma(std::uint64_t seed) {
  SplitMix64 rng(seed);
  const double theta = 0.25 + 2.0 * rng.uniform();
  return std::polar(1.0, rng.uniform() < 0.5 ? -theta : theta);
}

Tracker::Tracker(const CompiledShape& shape, const CoefficientPolynomials& coefficients, Arc arc,
                 const Complex* end_coefficients, const TrackerOptions& options)
    : shape_(shape),
      poly_(alongArc(coefficients, arc.gamma)),
      end_(end_coefficients),
      options_(options),
      scratch_(shape),
      c_(coefficients.terms),
      dc_(coefficients.terms) {
  const int n = shape.variables();
  f_.resize(n);
  fs_.resize(n);
  J_.resize(n, n);
  k2_.resize(n);
  k3_.resize(n);
  k4_.resize(n);
  z_.resize(n);
}

void Tracker::coefficientsAt(double s) {
  if (s == s_cached_) return;
  poly_.evaluate(s, c_.data(), dc_.data());
  s_cached_ = s;
}

bool Tracker::velocity(const CVec& x, double s, CVec& v) {
  coefficientsAt(s);
  evaluate(shape_, c_.data(), dc_.data(), x, scratch_, nullptr, &J_, &fs_);  // f unused
  if (!lu_.factor(J_)) return false;
  lu_.solve(fs_, v);
  v = -v;
  return finite(v);
}

double Tracker::newton(CVec& x, double s, CVec* v) {
  coefficientsAt(s);
  evaluate(shape_, c_.data(), v ? dc_.data() : nullptr, x, scratch_, &f_, &J_, v ? &fs_ : nullptr);
  if (!lu_.factor(J_)) return -1.0;
  if (v) {
    lu_.solve(f_, fs_, d_, *v);
    *v = -*v;
  } else {
    lu_.solve(f_, d_);
  }
  if (!finite(d_)) return -1.0;
  x -= d_;
  return normInf(d_);
}

double Tracker::chord(CVec& x) {
  evaluate(shape_, c_.data(), nullptr, x, scratch_, &f_, nullptr, nullptr);
  lu_.solve(f_, d_);
  if (!finite(d_)) return -1.0;
  x -= d_;
  return normInf(d_);
}

bool Tracker::rungeKutta(const CVec& x, const CVec& v, double s, double h, double s1, CVec& y) {
  z_ = x + (0.5 * h) * v;
  if (!velocity(z_, s + 0.5 * h, k2_)) return false;
  z_ = x + (0.5 * h) * k2_;
  if (!velocity(z_, s + 0.5 * h, k3_)) return false;
  z_ = x + h * k3_;
  if (!velocity(z_, s1, k4_)) return false;
  y = x + (h / 6.0) * (v + 2.0 * (k2_ + k3_) + k4_);
  return true;
}

PathEnd Tracker::track(const CVec& start) {
  PathEnd end;
  const int n = shape_.variables();
  CVec x = start, v(n), y(n), v_next(n);
  lu_.reset();  // no pivot order from the last path
  const double limit = options_.divergence * (1.0 + normInf(start));
  double s = 0.0, h = options_.initial_step;
  if (!velocity(x, s, v)) {
    end.x = x;
    return end;
  }
  while (s < 1.0) {
    if (end.steps >= options_.max_steps) {
      end.x = x;
      return end;
    }
    const double hh = std::min(h, 1.0 - s);
    const double s1 = (hh == 1.0 - s) ? 1.0 : s + hh;
    // RK4; v is the velocity at x carried over from the last corrector.
    bool ok = rungeKutta(x, v, s, hh, s1, y);
    double e1 = 0.0;
    if (ok) {
      const double scale = 1.0 + normInf(y);
      e1 = newton(y, s1, &v_next) / scale;
      ok = e1 >= 0.0 && e1 <= options_.max_error;
      // A large first correction must be followed by a much smaller one (Newton contracting
      // quadratically from inside the path's basin, not sitting between two paths).
      if (ok && e1 > options_.confirm_error) {
        const double e2 = chord(y) / scale;
        ok = e2 >= 0.0 && e2 <= 0.1 * e1;
      }
    }
    ++end.steps;
    if (ok) {
      x = y;
      v = v_next;
      s = s1;
      const double grow = e1 > 0.0 ? 0.9 * std::pow(options_.target_error / e1, 0.2) : 3.0;
      h = std::min(options_.max_step, hh * std::clamp(grow, 0.3, 3.0));
      if (normInf(x) > limit) {
        end.x = x;
        end.status = PathStatus::kAtInfinity;
        return end;
      }
    } else {
      ++end.rejected;
      h = 0.5 * hh;
      if (h < options_.min_step) {
        end.x = x;
        end.status = normInf(x) > 1e4 * (1.0 + normInf(start)) ? PathStatus::kAtInfinity
                                                               : PathStatus::kFailed;
        return end;
      }
    }
  }
  if (end_) polish(shape_, end_, x, scratch_, 4);
  end.x = x;
  end.status = finite(x) ? PathStatus::kFinite : PathStatus::kFailed;
  return end;
}

double polish(const CompiledShape& shape, const Complex* c, CVec& x, EvalScratch& scratch,
              int iterations) {
  const int n = shape.variables();
  CVec f(n);
  CMat J(n, n);
  double last = -1.0;
  for (int it = 0; it < iterations; ++it) {
    evaluate(shape, c, nullptr, x, scratch, &f, &J, nullptr);
    SmallLU lu;
    CVec d(n);
    if (!lu.factor(J)) return -1.0;
    lu.solve(f, d);
    if (!finite(d)) return -1.0;
    x -= d;
    last = normInf(d) / (1.0 + normInf(x));
    if (last < 1e-15) break;
  }
  return last;
}

}  // namespace relpos::complete::detail
