#pragma once
// Evaluation of a SystemShape with given coefficients: values and Jacobian at a complex point (the
// tracker's inner loop), and enclosures over interval boxes (the Krawczyk test). Every monomial of
// the shape, and every monomial its partial derivatives need, is a node of one product tree
// (node = parent · x_var), evaluated once per point and shared by all equations.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete::detail {

using CVec = Eigen::Matrix<Complex, Eigen::Dynamic, 1, 0, kMaxVariables, 1>;
using CMat =
    Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxVariables, kMaxVariables>;
using RVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxVariables, 1>;
using RMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxVariables, kMaxVariables>;

// The largest of a complex vector's real and imaginary parts, in magnitude (the tracker's and the
// certifier's scale of a point).
inline double normInf(const CVec& x) {
  double m = 0.0;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    m = std::max(m, std::max(std::abs(x[i].real()), std::abs(x[i].imag())));
  return m;
}

// Complex product without the C99 NaN recovery of std::complex's operator* (a library call in
// GCC without -ffast-math): the tracker multiplies finite numbers, and a NaN fails its checks.
inline Complex mul(const Complex& a, const Complex& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

// A complex number as one 16-byte vector (re, im) (the GCC and Clang vector extension: SSE2 on
// x86-64, NEON on AArch64). The tracker's arithmetic was bound by scalar multiplies and adds; in
// pairs a product-sum k·m takes two packed products, (kr mr, ki mi) and (kr mi, ki mr), summed
// apart and combined once at the end of the sum. Loads and stores by memcpy: std::complex and
// double[2] storage alike, no alignment assumed.
using Pair = double __attribute__((vector_size(16)));
inline Pair loadPair(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void storePair(double* p, Pair v) { std::memcpy(p, &v, sizeof v); }
inline Pair swapPair(Pair v) { return Pair{v[1], v[0]}; }
// z · w for z = (zr, zi) given as z and (zi, zr), w as wa = (wr, wr) and wb = (−wi, wi).
inline Pair mulPair(Pair z, Pair z_swapped, Pair wa, Pair wb) { return wa * z + wb * z_swapped; }

class CompiledShape {
 public:
  explicit CompiledShape(const SystemShape& shape);

  struct Node {
    std::uint16_t parent = 0;
    std::uint8_t var = 0;
  };
  // ∂(monomial of term) / ∂x_var = power · node.
  struct Partial {
    std::uint32_t term = 0;
    std::uint16_t equation = 0;
    std::uint16_t node = 0;
    std::uint8_t var = 0;
    std::uint8_t power = 0;
  };

  int variables() const { return variables_; }
  int terms() const { return static_cast<int>(term_node_.size()); }
  int nodes() const { return static_cast<int>(nodes_.size()); }
  const std::vector<Node>& nodeList() const { return nodes_; }
  const std::vector<std::uint16_t>& termNode() const { return term_node_; }
  const std::vector<std::uint16_t>& termEquation() const { return term_equation_; }
  const std::vector<Partial>& partials() const { return partials_; }
  // evaluate()'s lists: the terms as (coefficient, node) ordered by equation, and the partials by
  // (equation, var), a partial of power p listed p times (no weight to multiply). Each run of
  // equal keys sums in registers and is written once (accumulating in place serialises on the
  // store). An entry holds byte offsets, of the coefficient (16 per term) and of the node's
  // values (32 per node, EvalScratch): the sums' addresses without a multiply.
  struct Entry {
    std::uint32_t coefficient = 0;
    std::uint32_t node = 0;
    Entry(std::uint32_t term, std::uint16_t n) : coefficient(16 * term), node(32u * n) {}
  };
  struct Run {
    std::uint16_t equation = 0;
    std::uint8_t var = 0;
    std::uint32_t begin = 0, end = 0;
  };
  const std::vector<Entry>& termEntries() const { return term_entries_; }
  const std::vector<Run>& termRuns() const { return term_runs_; }
  const std::vector<Entry>& jacobianEntries() const { return jacobian_entries_; }
  const std::vector<Run>& jacobianRuns() const { return jacobian_runs_; }
  // Largest monomial degree of each equation (total-degree start systems, Bézout number).
  const std::vector<int>& equationDegrees() const { return degrees_; }

 private:
  int variables_ = 0;
  std::vector<Node> nodes_;  // nodes_[0] = 1
  std::vector<std::uint16_t> term_node_;
  std::vector<std::uint16_t> term_equation_;
  std::vector<Partial> partials_;
  std::vector<int> degrees_;
  std::vector<Entry> term_entries_;
  std::vector<Run> term_runs_;
  std::vector<Entry> jacobian_entries_;
  std::vector<Run> jacobian_runs_;
};

// Scratch for evaluate(): one per tracker, sized once (no allocation per evaluation). Node k's
// value as (re, im, im, re) at values[4 k]: the pair and its swap, both loaded by the sums.
struct EvalScratch {
  std::vector<double> values;
  explicit EvalScratch(const CompiledShape& s) : values(4 * static_cast<std::size_t>(s.nodes())) {}
};

// f = F(x) with coefficients c if f; J = ∂F/∂x if J; fs = Σ dc_t · m_t(x) if dc and fs (the
// derivative of the homotopy along its parameter when dc are the coefficients' derivatives).
void evaluate(const CompiledShape& shape, const Complex* c, const Complex* dc, const CVec& x,
              EvalScratch& scratch, CVec* f, CMat* J, CVec* fs);

// Interval enclosure of F and its Jacobian over a box. X: the box's scalar (a real interval, or
// ComplexBox below), C: the coefficients' scalar (a real interval or ComplexBox). The caller
// provides the rounding mode the interval type needs. values: shape.nodes() scratch; J row-major
// n × n (may be null).
template <class X, class C>
void evaluateBox(const CompiledShape& shape, const C* c, const X* x, X* values, X* f, X* J) {
  const int n = shape.variables();
  const auto& nodes = shape.nodeList();
  values[0] = X(1.0);
  for (int k = 1; k < shape.nodes(); ++k) values[k] = values[nodes[k].parent] * x[nodes[k].var];
  for (int e = 0; e < n; ++e) f[e] = X(0.0);
  const auto& tn = shape.termNode();
  const auto& te = shape.termEquation();
  for (int t = 0; t < shape.terms(); ++t) f[te[t]] = f[te[t]] + c[t] * values[tn[t]];
  if (!J) return;
  for (int i = 0; i < n * n; ++i) J[i] = X(0.0);
  for (const auto& p : shape.partials()) {
    X& out = J[p.equation * n + p.var];
    out = out + (c[p.term] * values[p.node]) * double(p.power);
  }
}

}  // namespace relpos::complete::detail
