#pragma once
// Evaluation of a SystemShape with given coefficients: values and Jacobian at a complex point (the
// tracker's inner loop), and enclosures over interval boxes (the Krawczyk test). Every monomial of
// the shape, and every monomial its partial derivatives need, is a node of one product tree
// (node = parent · x_var), evaluated once per point and shared by all equations.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete::detail {

using CVec = Eigen::Matrix<Complex, Eigen::Dynamic, 1, 0, kMaxVariables, 1>;
using CMat =
    Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxVariables, kMaxVariables>;
using RVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxVariables, 1>;
using RMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxVariables, kMaxVariables>;

// Complex product without the C99 NaN recovery of std::complex's operator* (a library call in
// GCC without -ffast-math): the tracker multiplies finite numbers, and a NaN fails its checks.
inline Complex mul(const Complex& a, const Complex& b) {
  return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

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
    double weight = 0.0;  // = power (a conversion less in the inner loop)
  };

  int variables() const { return variables_; }
  int terms() const { return static_cast<int>(term_node_.size()); }
  int nodes() const { return static_cast<int>(nodes_.size()); }
  const std::vector<Node>& nodeList() const { return nodes_; }
  const std::vector<std::uint16_t>& termNode() const { return term_node_; }
  const std::vector<std::uint16_t>& termEquation() const { return term_equation_; }
  const std::vector<Partial>& partials() const { return partials_; }
  // The terms ordered by equation, and the partials by (equation, var): each run of equal keys
  // sums in a register and is written once (accumulating in place serialises on the store).
  struct Run {
    std::uint16_t equation = 0;
    std::uint8_t var = 0;
    std::uint32_t begin = 0, end = 0;
  };
  const std::vector<std::uint32_t>& termOrder() const { return term_order_; }
  const std::vector<Run>& termRuns() const { return term_runs_; }
  const std::vector<Partial>& sortedPartials() const { return sorted_partials_; }
  const std::vector<Run>& partialRuns() const { return partial_runs_; }
  // Largest monomial degree of each equation (total-degree start systems, Bézout number).
  const std::vector<int>& equationDegrees() const { return degrees_; }

 private:
  int variables_ = 0;
  std::vector<Node> nodes_;  // nodes_[0] = 1
  std::vector<std::uint16_t> term_node_;
  std::vector<std::uint16_t> term_equation_;
  std::vector<Partial> partials_;
  std::vector<int> degrees_;
  std::vector<std::uint32_t> term_order_;
  std::vector<Run> term_runs_;
  std::vector<Partial> sorted_partials_;
  std::vector<Run> partial_runs_;
};

// Scratch for evaluate(): one per tracker, sized once (no allocation per evaluation).
struct EvalScratch {
  std::vector<Complex> values;
  explicit EvalScratch(const CompiledShape& s) : values(s.nodes()) {}
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
