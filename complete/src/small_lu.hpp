#pragma once
// LU with pivoting for the tracker's small complex systems (n ≤ 16), without allocation, on
// complex pairs (polynomial_eval.hpp). Pivots by |re| + |im| (Eigen's PartialPivLU takes
// std::abs, a hypot per entry, which was a sixth of the tracking time).
//
// Along a path the Jacobian changes a little from one factorization to the next, and so does
// its pivot order: the rows are taken in the last order as long as each pivot is at least half
// of the largest entry below it (threshold pivoting: the multipliers stay small), which takes
// the search for the pivot and the row exchanges off the chain of dependent operations (a fifth
// of the factorization's time); else the factorization starts again with partial pivoting.
// reset() forgets the order: each path starts from the same state whichever paths the tracker
// followed before (the same results for every thread count).
#include <algorithm>
#include <cmath>
#include <utility>

#include "polynomial_eval.hpp"

namespace relpos::complete::detail {

class SmallLU {
 public:
  void reset() { n_ = 0; }

  // False if a pivot is zero or not finite (the matrix is singular to working precision).
  bool factor(const CMat& a) {
    const int n = static_cast<int>(a.rows());
    if (n == n_ && factorInOrder(a)) return true;
    n_ = 0;
    if (!factorPartial(a)) return false;
    n_ = n;
    return true;
  }

  // x = A⁻¹ b (x may alias b).
  void solve(const CVec& b, CVec& x) const {
    Pair xs[kMaxVariables];
    loadPermuted(b, xs);
    substitute(xs);
    store(xs, x);
  }
  // Two right-hand sides at once: the two chains of dependent operations interleave.
  void solve(const CVec& b, const CVec& c, CVec& x, CVec& y) const {
    Pair xs[kMaxVariables], ys[kMaxVariables];
    loadPermuted(b, xs);
    loadPermuted(c, ys);
    substitute(xs, ys);
    store(xs, x);
    store(ys, y);
  }

 private:
  // b's entries in the factorization's row order.
  void loadPermuted(const CVec& b, Pair* xs) const {
    const double* bv = reinterpret_cast<const double*>(b.data());
    for (int i = 0; i < n_; ++i) xs[i] = loadPair(bv + 2 * order_[i]);
  }
  void store(const Pair* xs, CVec& x) const {
    x.resize(n_);
    double* xv = reinterpret_cast<double*>(x.data());
    for (int i = 0; i < n_; ++i) storePair(xv + 2 * i, xs[i]);
  }
  // Forward and back substitution on the permuted right-hand sides, in place. By columns: once
  // x_j is final it leaves every later row at once (the rows' chains of dependent adds run side
  // by side; by rows each x_i waited for the sum before it).
  template <class... X>
  void substitute(X*... xs) const {
    const int n = n_;
    for (int j = 0; j < n; ++j) {
      const Pair* col = a_ + j * n;
      (eliminateBelow(col, j, xs), ...);
    }
    for (int j = n - 1; j >= 0; --j) {
      const Pair* col = a_ + j * n;
      (eliminateAbove(col, j, xs), ...);
    }
  }
  // x_i −= l_ij x_j for the rows below j.
  void eliminateBelow(const Pair* col, int j, Pair* xs) const {
    const Pair xa{xs[j][0], xs[j][0]}, xb{-xs[j][1], xs[j][1]};
    for (int i = j + 1; i < n_; ++i) xs[i] -= mulPair(col[i], swapPair(col[i]), xa, xb);
  }
  // x_j /= u_jj, then x_i −= u_ij x_j for the rows above j.
  void eliminateAbove(const Pair* col, int j, Pair* xs) const {
    const Pair d = inv_diag_[j];
    xs[j] = mulPair(xs[j], swapPair(xs[j]), Pair{d[0], d[0]}, Pair{-d[1], d[1]});
    const Pair xa{xs[j][0], xs[j][0]}, xb{-xs[j][1], xs[j][1]};
    for (int i = 0; i < j; ++i) xs[i] -= mulPair(col[i], swapPair(col[i]), xa, xb);
  }

  // Rows of a in order_ (row i of the factored matrix is row order_[i] of a).
  void loadRows(const CMat& a) {
    const int n = static_cast<int>(a.rows());
    const double* m = reinterpret_cast<const double*>(a.data());
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) a_[i + j * n] = loadPair(m + 2 * (order_[i] + j * n));
  }

  static double size(Pair z) { return std::abs(z[0]) + std::abs(z[1]); }

  bool factorInOrder(const CMat& a) {
    const int n = n_;
    loadRows(a);
    for (int k = 0; k < n; ++k) {
      const Pair* col = a_ + k * n;
      double largest = 0.0;
      for (int i = k + 1; i < n; ++i) largest = std::max(largest, size(col[i]));
      const double pivot = size(col[k]);
      if (!(pivot > 0.0) || !std::isfinite(pivot) || !(pivot >= 0.5 * largest)) return false;
      eliminate(k, n);
    }
    return true;
  }

  bool factorPartial(const CMat& a) {
    const int n = static_cast<int>(a.rows());
    for (int i = 0; i < n; ++i) order_[i] = i;
    loadRows(a);
    for (int k = 0; k < n; ++k) {
      const Pair* col = a_ + k * n;
      int p = k;
      double best = -1.0;
      for (int i = k; i < n; ++i) {
        const double v = size(col[i]);
        if (v > best) {
          best = v;
          p = i;
        }
      }
      if (!(best > 0.0) || !std::isfinite(best)) return false;
      if (p != k) {
        std::swap(order_[k], order_[p]);
        for (int j = 0; j < n; ++j) std::swap(a_[k + j * n], a_[p + j * n]);
      }
      eliminate(k, n);
    }
    return true;
  }

  // Column k's multipliers, then each later column updated in one contiguous sweep.
  void eliminate(int k, int n) {
    Pair* colk = a_ + k * n;
    const Pair d = colk[k];
    const double r = 1.0 / (d[0] * d[0] + d[1] * d[1]);
    const double ir = d[0] * r, ii = -d[1] * r;
    inv_diag_[k] = Pair{ir, ii};
    const Pair ia{ir, ir}, ib{-ii, ii};
    Pair ls[kMaxVariables];  // the multipliers' swaps
    for (int i = k + 1; i < n; ++i) {
      colk[i] = mulPair(colk[i], swapPair(colk[i]), ia, ib);
      ls[i] = swapPair(colk[i]);
    }
    for (int j = k + 1; j < n; ++j) {
      Pair* col = a_ + j * n;
      const Pair ua{col[k][0], col[k][0]}, ub{-col[k][1], col[k][1]};
      for (int i = k + 1; i < n; ++i) col[i] -= mulPair(colk[i], ls[i], ua, ub);
    }
  }

  Pair a_[kMaxVariables * kMaxVariables];  // column-major, leading dimension n
  Pair inv_diag_[kMaxVariables];
  int order_[kMaxVariables] = {};
  int n_ = 0;  // the size of the last factorization, 0: none (no order to reuse)
};

}  // namespace relpos::complete::detail
