#pragma once
// Brent's minimisation (parabolic steps, golden sections where a parabola is not trusted) started
// from a known point. Boost.Math's brent_find_minima starts from the interval's upper end instead,
// so on a non-unimodal interval it may descend into a worse basin than the one the caller's point
// (the nearest of the samples) lies in; its iteration is otherwise the one below (Boost Software
// License 1.0, boost/math/tools/minima.hpp).
#include <cmath>

namespace relpos::detail {

// A local minimum of f in [lo, hi] from x (f(x) = fx, nearer than f at lo and hi for a bracket):
// every point weighed is kept by f's caller if it wants the nearest. Ends when the interval left is
// within tolerance·|x| + tolerance/4 of x, after max_iter evaluations, or where two evaluations in
// a row weigh exactly f(x).
template <class F>
double brentMinimumFrom(F&& f, double lo, double hi, double x, double fx, double tolerance,
                        int max_iter) {
  constexpr double kGolden = 0.3819660112501051;  // 2 − φ
  double w = x, v = x, fw = fx, fv = fx;
  double delta = 0.0, delta2 = 0.0;
  int ties = 0;
  for (int count = 0; count < max_iter; ++count) {
    const double mid = 0.5 * (lo + hi);
    const double fract1 = tolerance * std::abs(x) + tolerance / 4, fract2 = 2 * fract1;
    if (std::abs(x - mid) <= fract2 - 0.5 * (hi - lo)) break;
    bool golden = true;
    if (std::abs(delta2) > fract1) {  // a parabola through x, w, v
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double td = delta2;
      delta2 = delta;
      if (!(std::abs(p) >= std::abs(q * td / 2) || p <= q * (lo - x) || p >= q * (hi - x))) {
        golden = false;
        delta = p / q;
        const double u = x + delta;
        if (u - lo < fract2 || hi - u < fract2) delta = mid - x < 0 ? -fract1 : fract1;
      }
    }
    if (golden) {
      delta2 = x >= mid ? lo - x : hi - x;
      delta = kGolden * delta2;
    }
    const double u = std::abs(delta) >= fract1 ? x + delta : (delta > 0 ? x + fract1 : x - fract1);
    const double fu = f(u);
    // Two points in a row weighing exactly what x does: f is flat here to the last bit (a plateau
    // of the metric, or the rounding's width about a smooth minimum), and x is as near as any.
    ties = fu == fx ? ties + 1 : 0;
    if (ties == 2) break;
    if (fu <= fx) {
      (u >= x ? lo : hi) = x;
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {
      (u < x ? lo : hi) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return x;
}

}  // namespace relpos::detail
