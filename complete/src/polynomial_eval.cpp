#include "polynomial_eval.hpp"

#include <algorithm>
#include <cassert>
#include <map>
#include <stdexcept>

namespace relpos::complete::detail {
namespace {

// A monomial as its sorted variable list; the key orders nodes so a parent precedes its children.
using Key = std::vector<std::uint8_t>;

class NodeBuilder {
 public:
  explicit NodeBuilder(std::vector<CompiledShape::Node>& nodes) : nodes_(nodes) {
    nodes_.push_back({});
    index_[Key{}] = 0;
  }
  // The node of monomial `key` (sorted), creating it and its prefix chain if new.
  std::uint16_t node(const Key& key) {
    auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    Key parent(key.begin(), key.end() - 1);
    const std::uint16_t p = node(parent);
    if (nodes_.size() >= 65535) throw std::length_error("relpos::complete: too many monomials");
    const auto id = static_cast<std::uint16_t>(nodes_.size());
    nodes_.push_back({p, key.back()});
    index_[key] = id;
    return id;
  }

 private:
  std::vector<CompiledShape::Node>& nodes_;
  std::map<Key, std::uint16_t> index_;
};

}  // namespace

CompiledShape::CompiledShape(const SystemShape& shape) : variables_(shape.variables) {
  if (variables_ < 1 || variables_ > kMaxVariables)
    throw std::invalid_argument("relpos::complete: variables out of range");
  NodeBuilder builder(nodes_);
  degrees_.assign(variables_, 0);
  std::vector<std::uint16_t> monomial_node(shape.monomials.size());
  for (std::size_t m = 0; m < shape.monomials.size(); ++m) {
    const Monomial& mono = shape.monomials[m];
    if (mono.degree > kMaxMonomialDegree)
      throw std::invalid_argument("relpos::complete: monomial degree above 4");
    Key key(mono.vars.begin(), mono.vars.begin() + mono.degree);
    for (auto v : key)
      if (v >= variables_) throw std::invalid_argument("relpos::complete: variable out of range");
    std::sort(key.begin(), key.end());
    monomial_node[m] = builder.node(key);
  }
  for (std::size_t t = 0; t < shape.terms.size(); ++t) {
    const auto& term = shape.terms[t];
    if (term.equation >= variables_ || term.monomial >= shape.monomials.size())
      throw std::invalid_argument("relpos::complete: term out of range");
    term_node_.push_back(monomial_node[term.monomial]);
    term_equation_.push_back(term.equation);
    const Monomial& mono = shape.monomials[term.monomial];
    degrees_[term.equation] = std::max<int>(degrees_[term.equation], mono.degree);
    Key key(mono.vars.begin(), mono.vars.begin() + mono.degree);
    std::sort(key.begin(), key.end());
    // One partial per distinct variable: its power, and the monomial with one factor removed.
    for (std::size_t i = 0; i < key.size();) {
      std::size_t j = i;
      while (j < key.size() && key[j] == key[i]) ++j;
      Key reduced = key;
      reduced.erase(reduced.begin() + static_cast<std::ptrdiff_t>(i));
      Partial p;
      p.term = static_cast<std::uint32_t>(t);
      p.equation = term.equation;
      p.node = builder.node(reduced);
      p.var = key[i];
      p.power = static_cast<std::uint8_t>(j - i);
      p.weight = double(p.power);
      partials_.push_back(p);
      i = j;
    }
  }
  for (std::uint32_t t = 0; t < term_node_.size(); ++t) term_order_.push_back(t);
  std::stable_sort(term_order_.begin(), term_order_.end(), [&](std::uint32_t a, std::uint32_t b) {
    return term_equation_[a] < term_equation_[b];
  });
  for (std::uint32_t i = 0; i < term_order_.size(); ++i) {
    const auto eq = term_equation_[term_order_[i]];
    if (term_runs_.empty() || term_runs_.back().equation != eq) term_runs_.push_back({eq, 0, i, i});
    term_runs_.back().end = i + 1;
  }
  sorted_partials_ = partials_;
  std::stable_sort(sorted_partials_.begin(), sorted_partials_.end(),
                   [](const Partial& a, const Partial& b) {
                     return a.equation != b.equation ? a.equation < b.equation : a.var < b.var;
                   });
  for (std::uint32_t i = 0; i < sorted_partials_.size(); ++i) {
    const Partial& p = sorted_partials_[i];
    if (partial_runs_.empty() || partial_runs_.back().equation != p.equation ||
        partial_runs_.back().var != p.var)
      partial_runs_.push_back({p.equation, p.var, i, i});
    partial_runs_.back().end = i + 1;
  }
}

// On raw doubles (std::complex is layout-compatible with double[2]): with std::complex values
// GCC stored each product's parts separately and reloaded them as a pair, a store-forwarding
// stall per term that took three quarters of the tracking time.
void evaluate(const CompiledShape& shape, const Complex* c, const Complex* dc, const CVec& x,
              EvalScratch& scratch, CVec* f, CMat* J, CVec* fs) {
  const int n = shape.variables();
  const auto& nodes = shape.nodeList();
  double* v = reinterpret_cast<double*>(scratch.values.data());
  const double* xv = reinterpret_cast<const double*>(x.data());
  const double* cv = reinterpret_cast<const double*>(c);
  v[0] = 1.0;
  v[1] = 0.0;
  for (int k = 1; k < shape.nodes(); ++k) {
    const double* a = v + 2 * nodes[k].parent;
    const double* b = xv + 2 * nodes[k].var;
    v[2 * k] = a[0] * b[0] - a[1] * b[1];
    v[2 * k + 1] = a[0] * b[1] + a[1] * b[0];
  }
  const auto& tn = shape.termNode();
  const auto& order = shape.termOrder();
  const double* dcv = reinterpret_cast<const double*>(dc);
  if (!dc) fs = nullptr;
  if (f) f->setZero(n);
  if (fs) fs->setZero(n);
  // Σ k_t m_t over one equation's terms, for the coefficients kv.
  auto sum = [&](const CompiledShape::Run& run, const double* kv) {
    double re = 0.0, im = 0.0;
    for (std::uint32_t i = run.begin; i < run.end; ++i) {
      const std::uint32_t t = order[i];
      const double* m = v + 2 * tn[t];
      const double* k = kv + 2 * t;
      re += k[0] * m[0] - k[1] * m[1];
      im += k[0] * m[1] + k[1] * m[0];
    }
    return Complex(re, im);
  };
  for (const auto& run : shape.termRuns()) {
    if (f) (*f)[run.equation] = sum(run, cv);
    if (fs) (*fs)[run.equation] = sum(run, dcv);
  }
  if (!J) return;
  J->setZero(n, n);
  const auto& partials = shape.sortedPartials();
  for (const auto& run : shape.partialRuns()) {
    double re = 0.0, im = 0.0;
    for (std::uint32_t i = run.begin; i < run.end; ++i) {
      const auto& p = partials[i];
      const double* m = v + 2 * p.node;
      const double* k = cv + 2 * p.term;
      const double w = p.weight;
      re += w * (k[0] * m[0] - k[1] * m[1]);
      im += w * (k[0] * m[1] + k[1] * m[0]);
    }
    (*J)(run.equation, run.var) = Complex(re, im);
  }
}

}  // namespace relpos::complete::detail
