#pragma once
// Sparse polynomials in the unknowns x with coefficients of a scalar type S: the one piece of
// algebra every encoding (pose_family.cpp, line_family.cpp) writes its equations in, so that the
// same formulas give the coefficients for complex parameters (Complex), their enclosures
// (Interval) and the system's shape and coefficient degrees (Structure). Products are the
// algebraic ones (no conjugation of the scalars), so identities such as N(ab) = N(a) N(b) hold for
// complex parameters too.
#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete {

// A monomial as one integer: the degree in bits 16-18, the sorted variable indices in 4 bits each
// (bits 12-15 the first). Ordered by degree first, so a polynomial's terms list low degrees first.
using MonomialKey = std::uint32_t;

inline int keyDegree(MonomialKey k) { return static_cast<int>(k >> 16); }
inline int keyVar(MonomialKey k, int i) { return static_cast<int>((k >> (12 - 4 * i)) & 15u); }

inline MonomialKey keyOf(const int* vars, int degree) {
  MonomialKey k = static_cast<MonomialKey>(degree) << 16;
  for (int i = 0; i < degree; ++i) k |= static_cast<MonomialKey>(vars[i]) << (12 - 4 * i);
  return k;
}

inline MonomialKey multiplyKeys(MonomialKey a, MonomialKey b) {
  const int da = keyDegree(a), db = keyDegree(b);
  if (da + db > kMaxMonomialDegree) throw std::logic_error("monomial degree above 4");
  int vars[kMaxMonomialDegree];
  for (int i = 0; i < da; ++i) vars[i] = keyVar(a, i);
  for (int i = 0; i < db; ++i) vars[da + i] = keyVar(b, i);
  std::sort(vars, vars + da + db);
  return keyOf(vars, da + db);
}

inline Monomial monomialOf(MonomialKey k) {
  Monomial m;
  m.degree = static_cast<std::uint8_t>(keyDegree(k));
  for (int i = 0; i < m.degree; ++i) m.vars[i] = static_cast<std::uint8_t>(keyVar(k, i));
  return m;
}

// The structure of a coefficient: its degree as a polynomial in the parameters, -1 for an
// identical zero. Sums take the larger degree, products add them: an upper bound (cancellations
// are not seen), so the shape built from it holds every term a member can have.
struct Structure {
  int degree = -1;
  Structure() = default;
  explicit Structure(double c) : degree(c != 0.0 ? 0 : -1) {}
  static Structure parameter() {
    Structure s;
    s.degree = 1;
    return s;
  }
  friend Structure operator+(Structure a, Structure b) {
    a.degree = std::max(a.degree, b.degree);
    return a;
  }
  friend Structure operator-(Structure a, Structure b) { return a + b; }
  friend Structure operator-(Structure a) { return a; }
  friend Structure operator*(Structure a, Structure b) {
    a.degree = a.degree < 0 || b.degree < 0 ? -1 : a.degree + b.degree;
    return a;
  }
};

template <typename S>
struct Poly {
  std::vector<std::pair<MonomialKey, S>> terms;  // sorted by key, each key once

  static Poly constant(const S& c) {
    Poly p;
    p.terms.push_back({0u, c});
    return p;
  }
  static Poly variable(int i) {
    Poly p;
    p.terms.push_back({keyOf(&i, 1), S(1.0)});
    return p;
  }
};

namespace detail {
template <typename S>
Poly<S> merged(std::vector<std::pair<MonomialKey, S>> t) {
  std::stable_sort(t.begin(), t.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Poly<S> out;
  for (auto& kv : t) {
    if (!out.terms.empty() && out.terms.back().first == kv.first)
      out.terms.back().second = out.terms.back().second + kv.second;
    else
      out.terms.push_back(std::move(kv));
  }
  return out;
}
}  // namespace detail

template <typename S>
Poly<S> operator+(const Poly<S>& a, const Poly<S>& b) {
  std::vector<std::pair<MonomialKey, S>> t = a.terms;
  t.insert(t.end(), b.terms.begin(), b.terms.end());
  return detail::merged(std::move(t));
}
template <typename S>
Poly<S> operator-(const Poly<S>& a) {
  Poly<S> out = a;
  for (auto& kv : out.terms) kv.second = -kv.second;
  return out;
}
template <typename S>
Poly<S> operator-(const Poly<S>& a, const Poly<S>& b) {
  return a + (-b);
}
template <typename S>
Poly<S> operator*(const S& c, const Poly<S>& a) {
  Poly<S> out = a;
  for (auto& kv : out.terms) kv.second = c * kv.second;
  return out;
}
template <typename S>
Poly<S> operator*(const Poly<S>& a, const Poly<S>& b) {
  std::vector<std::pair<MonomialKey, S>> t;
  t.reserve(a.terms.size() * b.terms.size());
  for (const auto& x : a.terms)
    for (const auto& y : b.terms)
      t.push_back({multiplyKeys(x.first, y.first), x.second * y.second});
  return detail::merged(std::move(t));
}

// The value at complex x.
inline Complex evaluate(const Poly<Complex>& p, const Complex* x) {
  Complex sum = 0.0;
  for (const auto& [key, c] : p.terms) {
    Complex m = c;
    for (int i = 0; i < keyDegree(key); ++i) m *= x[keyVar(key, i)];
    sum += m;
  }
  return sum;
}

// Quaternions (w, x, y, z) of polynomials, multiplied algebraically.
template <typename S>
using Quat = std::array<Poly<S>, 4>;

template <typename S>
Quat<S> operator*(const Quat<S>& a, const Quat<S>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
template <typename S>
Quat<S> operator+(const Quat<S>& a, const Quat<S>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]};
}
template <typename S>
Quat<S> operator-(const Quat<S>& a, const Quat<S>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]};
}
template <typename S>
Quat<S> operator*(const S& c, const Quat<S>& a) {
  return {c * a[0], c * a[1], c * a[2], c * a[3]};
}
template <typename S>
Quat<S> conjugate(const Quat<S>& a) {
  return {a[0], -a[1], -a[2], -a[3]};
}
// Σ a_i b_i over the four components (N(a) for a = b).
template <typename S>
Poly<S> dot4(const Quat<S>& a, const Quat<S>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}
// n · vec(a) for a constant 3-vector n.
template <typename S>
Poly<S> dotVec(const S* n, const Quat<S>& a) {
  return n[0] * a[1] + n[1] * a[2] + n[2] * a[3];
}
// The quaternion of the variables first, first + 1, … first + 3.
template <typename S>
Quat<S> variableQuat(int first) {
  return {Poly<S>::variable(first), Poly<S>::variable(first + 1), Poly<S>::variable(first + 2),
          Poly<S>::variable(first + 3)};
}
// The pure quaternion (0, v) of a constant 3-vector.
template <typename S>
Quat<S> pureQuat(const S* v) {
  return {Poly<S>{}, Poly<S>::constant(v[0]), Poly<S>::constant(v[1]), Poly<S>::constant(v[2])};
}

}  // namespace relpos::complete
