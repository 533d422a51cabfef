#pragma once
// Forward-mode derivatives in the six local coordinates of a pose (chart.hpp): a value and its
// gradient, over any scalar with + − × ÷ (double for Newton steps, the interval type FI for the
// proofs: the gradient's enclosure over a box is what Krawczyk's test and the mean-value form
// need). Written out rather than Eigen's AutoDiffScalar, whose derivative vector is dynamic
// (an allocation per operation) and which does not take Boost.Interval as its scalar.
#include <array>

namespace relpos::complete::detail {

template <typename S>
struct Dual {
  static constexpr int kN = 6;
  S v{};
  std::array<S, kN> g{};

  Dual() = default;
  // A constant: zero gradient.
  Dual(const S& value) : v(value) {  // NOLINT(google-explicit-constructor): constants mix in
    g.fill(S(0.0));
  }
  // The coordinate `i` itself.
  static Dual variable(const S& value, int i) {
    Dual d(value);
    d.g[i] = S(1.0);
    return d;
  }
};

template <typename S>
Dual<S> operator+(const Dual<S>& a, const Dual<S>& b) {
  Dual<S> r;
  r.v = a.v + b.v;
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = a.g[i] + b.g[i];
  return r;
}
template <typename S>
Dual<S> operator-(const Dual<S>& a, const Dual<S>& b) {
  Dual<S> r;
  r.v = a.v - b.v;
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = a.g[i] - b.g[i];
  return r;
}
template <typename S>
Dual<S> operator-(const Dual<S>& a) {
  Dual<S> r;
  r.v = -a.v;
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = -a.g[i];
  return r;
}
template <typename S>
Dual<S> operator*(const Dual<S>& a, const Dual<S>& b) {
  Dual<S> r;
  r.v = a.v * b.v;
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = a.g[i] * b.v + a.v * b.g[i];
  return r;
}
template <typename S>
Dual<S> operator*(const Dual<S>& a, double k) {
  Dual<S> r;
  r.v = a.v * S(k);
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = a.g[i] * S(k);
  return r;
}
template <typename S>
Dual<S> operator/(const Dual<S>& a, const Dual<S>& b) {
  Dual<S> r;
  r.v = a.v / b.v;
  // (a/b)' = (a' − (a/b) b') / b
  for (int i = 0; i < Dual<S>::kN; ++i) r.g[i] = (a.g[i] - r.v * b.g[i]) / b.v;
  return r;
}

}  // namespace relpos::complete::detail
