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
      partials_.push_back(p);
      i = j;
    }
  }
}

void evaluate(const CompiledShape& shape, const Complex* c, const Complex* dc, const CVec& x,
              EvalScratch& scratch, CVec& f, CMat* J, CVec* fs) {
  const int n = shape.variables();
  const auto& nodes = shape.nodeList();
  Complex* values = scratch.values.data();
  values[0] = Complex(1.0, 0.0);
  for (int k = 1; k < shape.nodes(); ++k) values[k] = mul(values[nodes[k].parent], x[nodes[k].var]);
  f.setZero(n);
  const auto& tn = shape.termNode();
  const auto& te = shape.termEquation();
  const int terms = shape.terms();
  if (fs && dc) {
    fs->setZero(n);
    for (int t = 0; t < terms; ++t) {
      const Complex v = values[tn[t]];
      f[te[t]] += mul(c[t], v);
      (*fs)[te[t]] += mul(dc[t], v);
    }
  } else {
    for (int t = 0; t < terms; ++t) f[te[t]] += mul(c[t], values[tn[t]]);
  }
  if (!J) return;
  J->setZero(n, n);
  for (const auto& p : shape.partials())
    (*J)(p.equation, p.var) += double(p.power) * mul(c[p.term], values[p.node]);
}

}  // namespace relpos::complete::detail
