#include "test_families.hpp"

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <utility>

namespace relpos::complete::testing {
namespace {

Monomial mono(std::initializer_list<int> vars) {
  Monomial m;
  m.degree = static_cast<std::uint8_t>(vars.size());
  int i = 0;
  for (int v : vars) m.vars[i++] = static_cast<std::uint8_t>(v);
  return m;
}

void addTerm(SystemShape& s, int equation, const Monomial& m) {
  int index = -1;
  for (std::size_t i = 0; i < s.monomials.size(); ++i)
    if (s.monomials[i] == m) index = static_cast<int>(i);
  if (index < 0) {
    index = static_cast<int>(s.monomials.size());
    s.monomials.push_back(m);
  }
  s.terms.push_back({static_cast<std::uint16_t>(equation), static_cast<std::uint16_t>(index)});
}

// ---- conics
const Monomial kConic[6] = {mono({0, 0}), mono({0, 1}), mono({1, 1}),
                            mono({0}),    mono({1}),    mono({})};

// ---- Stewart: the terms in the order stewartTerms emits them.
template <class T>
using Quat = std::array<T, 4>;

template <class T>
Quat<T> qmul(const Quat<T>& a, const Quat<T>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// Leg polynomial coefficients: ee[p][q] (p ≤ q) for e_p e_q, eg[p][q] for e_p g_q (g·g has 4).
template <class T>
struct Leg {
  T ee[4][4];
  T eg[4][4];
};

template <class T>
Leg<T> leg(const T* a3, const T* b3, const T& d2) {
  const T zero(0.0), one(1.0);
  const Quat<T> a{zero, a3[0], a3[1], a3[2]}, b{zero, b3[0], b3[1], b3[2]};
  T M[4][4];  // v = M e + 2 g, column j = unit_j b − a unit_j
  for (int j = 0; j < 4; ++j) {
    Quat<T> u{zero, zero, zero, zero};
    u[j] = one;
    const Quat<T> l = qmul(u, b), r = qmul(a, u);
    for (int i = 0; i < 4; ++i) M[i][j] = l[i] - r[i];
  }
  Leg<T> out;
  for (int p = 0; p < 4; ++p)
    for (int q = 0; q < 4; ++q) {
      T s = zero;
      for (int k = 0; k < 4; ++k) s = s + M[k][p] * M[k][q];  // (Mᵀ M)_pq
      if (p == q) s = s - d2;
      out.ee[p][q] = s;
      out.eg[p][q] = T(4.0) * M[q][p];
    }
  return out;
}

// Emits (equation, monomial, coefficient) for every term, in one fixed order.
template <class T>
void stewartTerms(const T* p, const std::function<void(int, const Monomial&, const T&)>& emit) {
  const T one(1.0);
  for (int k = 0; k < 4; ++k) emit(0, mono({k, 4 + k}), one);
  const Leg<T> l1 = leg(p + 4, p + 7, p[10]);
  for (int eq = 1; eq <= 6; ++eq) {
    const int base = 4 + 7 * (eq - 1);
    const Leg<T> li = leg(p + base, p + base + 3, p[base + 6]);
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) {
        const T v1 = i == j ? l1.ee[i][i] : l1.ee[i][j] + l1.ee[j][i];
        const T vi = i == j ? li.ee[i][i] : li.ee[i][j] + li.ee[j][i];
        emit(eq, mono({i, j}), eq == 1 ? v1 : vi - v1);
      }
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        emit(eq, mono({i, 4 + j}), eq == 1 ? l1.eg[i][j] : li.eg[i][j] - l1.eg[i][j]);
    if (eq == 1)
      for (int j = 0; j < 4; ++j) emit(1, mono({4 + j, 4 + j}), T(4.0));
  }
  for (int k = 0; k < 4; ++k) emit(7, mono({k}), p[k]);
  emit(7, mono({}), T(-1.0));
}

template <class T>
void stewartCoefficients(const T* p, T* out) {
  int t = 0;
  stewartTerms<T>(p, [&](int, const Monomial&, const T& v) { out[t++] = v; });
}

}  // namespace

ConicFamily::ConicFamily() {
  shape_.variables = 2;
  for (int k = 0; k < 2; ++k)
    for (const Monomial& m : kConic) addTerm(shape_, k, m);
}

void ConicFamily::coefficients(const Complex* params, Complex* coeffs) const {
  for (int i = 0; i < 12; ++i) coeffs[i] = params[i];
}
void ConicFamily::coefficients(const Interval* params, Interval* coeffs) const {
  for (int i = 0; i < 12; ++i) coeffs[i] = params[i];
}

void ConicFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n;
  root[0] = {n(rng), n(rng)};
  root[1] = {n(rng), n(rng)};
  const Complex x = root[0], y = root[1];
  const Complex m[5] = {x * x, x * y, y * y, x, y};
  for (int k = 0; k < 2; ++k) {
    Complex s = 0.0;
    for (int i = 0; i < 5; ++i) {
      params[6 * k + i] = {n(rng), n(rng)};
      s += params[6 * k + i] * m[i];
    }
    params[6 * k + 5] = -s;  // the root lies on the conic
  }
}

DenseFamily::DenseFamily(int n, int d)
    : signature_("test:dense-" + std::to_string(n) + "-" + std::to_string(d)) {
  shape_.variables = n;
  // Every sorted variable list of length ≤ d, the constant last.
  std::vector<Monomial> monomials;
  std::function<void(Monomial, int)> grow = [&](Monomial m, int from) {
    if (m.degree > 0) monomials.push_back(m);
    if (m.degree == d) return;
    for (int v = from; v < n; ++v) {
      Monomial next = m;
      next.vars[next.degree++] = static_cast<std::uint8_t>(v);
      grow(next, v);
    }
  };
  grow(Monomial{}, 0);
  monomials.push_back(Monomial{});
  for (int k = 0; k < n; ++k)
    for (const Monomial& m : monomials) addTerm(shape_, k, m);
}

void DenseFamily::coefficients(const Complex* params, Complex* coeffs) const {
  for (int i = 0; i < parameterCount(); ++i) coeffs[i] = params[i];
}
void DenseFamily::coefficients(const Interval* params, Interval* coeffs) const {
  for (int i = 0; i < parameterCount(); ++i) coeffs[i] = params[i];
}

Complex DenseFamily::monomialValue(int term, const Complex* x) const {
  const Monomial& m = shape_.monomials[shape_.terms[term].monomial];
  Complex v = 1.0;
  for (int j = 0; j < m.degree; ++j) v *= x[m.vars[j]];
  return v;
}

void DenseFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  for (int i = 0; i < shape_.variables; ++i) root[i] = {g(rng), g(rng)};
  const int per = parameterCount() / shape_.variables;
  for (int k = 0; k < shape_.variables; ++k) {
    Complex s = 0.0;
    for (int j = 0; j + 1 < per; ++j) {
      const int t = k * per + j;
      params[t] = {g(rng), g(rng)};
      s += params[t] * monomialValue(t, root);
    }
    params[k * per + per - 1] = -s;  // the constant term
  }
}

StewartFamily::StewartFamily(std::string signature) : signature_(std::move(signature)) {
  shape_.variables = 8;
  std::vector<Complex> p(46, Complex(1.0, 0.0));
  stewartTerms<Complex>(p.data(),
                        [&](int eq, const Monomial& m, const Complex&) { addTerm(shape_, eq, m); });
}

void StewartFamily::coefficients(const Complex* params, Complex* coeffs) const {
  stewartCoefficients(params, coeffs);
}
void StewartFamily::coefficients(const Interval* params, Interval* coeffs) const {
  stewartCoefficients(params, coeffs);
}

void StewartFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n;
  auto z = [&] { return Complex(n(rng), n(rng)); };
  Quat<Complex> e, g;
  for (auto& v : e) v = z();
  for (auto& v : g) v = z();
  Complex ee = 0.0, eg = 0.0;
  for (int k = 0; k < 4; ++k) {
    ee += e[k] * e[k];
    eg += e[k] * g[k];
  }
  for (int k = 0; k < 4; ++k) g[k] -= eg / ee * e[k];  // Study quadric
  Complex ce = 0.0;
  for (int k = 0; k < 4; ++k) {
    params[k] = z();
    ce += params[k] * e[k];
  }
  for (int k = 0; k < 4; ++k) params[k] /= ce;  // chart
  for (int i = 0; i < 6; ++i) {
    Complex* a = params + 4 + 7 * i;
    for (int j = 0; j < 6; ++j) a[j] = z();
    const Quat<Complex> aq{0.0, a[0], a[1], a[2]}, bq{0.0, a[3], a[4], a[5]};
    const Quat<Complex> eb = qmul(e, bq), ae = qmul(aq, e);
    Complex vv = 0.0;
    for (int k = 0; k < 4; ++k) {
      const Complex v = eb[k] - ae[k] + 2.0 * g[k];
      vv += v * v;
    }
    a[6] = vv / ee;
  }
  for (int k = 0; k < 4; ++k) {
    root[k] = e[k];
    root[4 + k] = g[k];
  }
}

std::vector<double> stewartMemberAround(const StewartPose& pose,
                                        const std::array<std::array<double, 3>, 6>& a,
                                        const std::array<std::array<double, 3>, 6>& b,
                                        const std::array<double, 4>& c_raw) {
  std::vector<double> p(46);
  double ee = 0.0, ce = 0.0;
  for (int k = 0; k < 4; ++k) {
    ee += pose.e[k] * pose.e[k];
    ce += c_raw[k] * pose.e[k];
  }
  for (int k = 0; k < 4; ++k) p[k] = c_raw[k] / ce;
  for (int i = 0; i < 6; ++i) {
    const Quat<double> aq{0.0, a[i][0], a[i][1], a[i][2]}, bq{0.0, b[i][0], b[i][1], b[i][2]};
    const Quat<double> e{pose.e[0], pose.e[1], pose.e[2], pose.e[3]};
    const Quat<double> eb = qmul(e, bq), ae = qmul(aq, e);
    double vv = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double v = eb[k] - ae[k] + 2.0 * pose.g[k];
      vv += v * v;
    }
    for (int j = 0; j < 3; ++j) {
      p[4 + 7 * i + j] = a[i][j];
      p[4 + 7 * i + 3 + j] = b[i][j];
    }
    p[4 + 7 * i + 6] = vv / ee;
  }
  return p;
}

std::vector<double> randomStewartMember(std::uint64_t seed, StewartPose& pose) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 4; ++k) {
    pose.e[k] = u(rng);
    pose.g[k] = u(rng);
  }
  double eg = 0.0, ee = 0.0;
  for (int k = 0; k < 4; ++k) {
    eg += pose.e[k] * pose.g[k];
    ee += pose.e[k] * pose.e[k];
  }
  for (int k = 0; k < 4; ++k) pose.g[k] -= eg / ee * pose.e[k];  // Study quadric
  std::array<std::array<double, 3>, 6> a{}, b{};
  for (auto& v : a)
    for (auto& w : v) w = 2.0 * u(rng);
  for (auto& v : b)
    for (auto& w : v) w = u(rng);
  return stewartMemberAround(pose, a, b, {u(rng), u(rng), 1.5, u(rng)});
}

}  // namespace relpos::complete::testing
