#pragma once
// LU with partial pivoting for the tracker's small complex systems (n ≤ 16), in place, without
// allocation. Pivots by |re| + |im| (Eigen's PartialPivLU takes std::abs, a hypot per entry,
// which was a sixth of the tracking time).
#include <cmath>

#include "polynomial_eval.hpp"

namespace relpos::complete::detail {

class SmallLU {
 public:
  // False if a pivot is zero or not finite (the matrix is singular to working precision).
  bool factor(const CMat& a) {
    lu_ = a;
    n_ = static_cast<int>(a.rows());
    for (int k = 0; k < n_; ++k) {
      int p = k;
      double best = -1.0;
      for (int i = k; i < n_; ++i) {
        const double m = std::abs(lu_(i, k).real()) + std::abs(lu_(i, k).imag());
        if (m > best) {
          best = m;
          p = i;
        }
      }
      if (!(best > 0.0) || !std::isfinite(best)) return false;
      perm_[k] = p;
      if (p != k) lu_.row(k).swap(lu_.row(p));
      const Complex inv = recip(lu_(k, k));
      inv_diag_[k] = inv;
      for (int i = k + 1; i < n_; ++i) {
        const Complex l = mul(lu_(i, k), inv);
        lu_(i, k) = l;
        for (int j = k + 1; j < n_; ++j) lu_(i, j) -= mul(l, lu_(k, j));
      }
    }
    return true;
  }
  // x = A⁻¹ b (x may alias b).
  void solve(const CVec& b, CVec& x) const {
    x = b;
    for (int k = 0; k < n_; ++k)
      if (perm_[k] != k) std::swap(x[k], x[perm_[k]]);
    for (int i = 1; i < n_; ++i) {
      Complex s = x[i];
      for (int j = 0; j < i; ++j) s -= mul(lu_(i, j), x[j]);
      x[i] = s;
    }
    for (int i = n_ - 1; i >= 0; --i) {
      Complex s = x[i];
      for (int j = i + 1; j < n_; ++j) s -= mul(lu_(i, j), x[j]);
      x[i] = mul(s, inv_diag_[i]);
    }
  }

 private:
  static Complex recip(const Complex& z) {
    const double d = z.real() * z.real() + z.imag() * z.imag();
    return {z.real() / d, -z.imag() / d};
  }
  CMat lu_;
  int n_ = 0;
  int perm_[kMaxVariables] = {};
  Complex inv_diag_[kMaxVariables];
};

}  // namespace relpos::complete::detail
