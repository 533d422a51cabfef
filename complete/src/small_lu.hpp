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
    const int n = n_;
    // Column-major storage: column k's multipliers, then each later column updated in one
    // contiguous sweep.
    double* m = reinterpret_cast<double*>(lu_.data());
    auto at = [&](int i, int j) { return m + 2 * (i + j * n); };
    for (int k = 0; k < n; ++k) {
      int p = k;
      double best = -1.0;
      for (int i = k; i < n; ++i) {
        const double* z = at(i, k);
        const double v = std::abs(z[0]) + std::abs(z[1]);
        if (v > best) {
          best = v;
          p = i;
        }
      }
      if (!(best > 0.0) || !std::isfinite(best)) return false;
      perm_[k] = p;
      if (p != k)
        for (int j = 0; j < n; ++j) {
          std::swap(at(k, j)[0], at(p, j)[0]);
          std::swap(at(k, j)[1], at(p, j)[1]);
        }
      const double* d = at(k, k);
      const double dd = d[0] * d[0] + d[1] * d[1];
      const double ir = d[0] / dd, ii = -d[1] / dd;
      inv_diag_[k] = Complex(ir, ii);
      for (int i = k + 1; i < n; ++i) {
        double* z = at(i, k);
        const double r = z[0] * ir - z[1] * ii, q = z[0] * ii + z[1] * ir;
        z[0] = r;
        z[1] = q;
      }
      for (int j = k + 1; j < n; ++j) {
        const double* u = at(k, j);
        const double ur = u[0], ui = u[1];
        const double* l = at(0, k);
        double* col = at(0, j);
        for (int i = k + 1; i < n; ++i) {
          col[2 * i] -= l[2 * i] * ur - l[2 * i + 1] * ui;
          col[2 * i + 1] -= l[2 * i] * ui + l[2 * i + 1] * ur;
        }
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
  CMat lu_;
  int n_ = 0;
  int perm_[kMaxVariables] = {};
  Complex inv_diag_[kMaxVariables];
};

}  // namespace relpos::complete::detail
