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
  if (term_node_.size() >= (std::size_t(1) << 28))  // Entry's byte offsets in 32 bits
    throw std::length_error("relpos::complete: too many terms");
  std::vector<std::uint32_t> order(term_node_.size());
  for (std::uint32_t t = 0; t < order.size(); ++t) order[t] = t;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return term_equation_[a] < term_equation_[b];
  });
  for (std::uint32_t i = 0; i < order.size(); ++i) {
    const auto eq = term_equation_[order[i]];
    if (term_runs_.empty() || term_runs_.back().equation != eq) term_runs_.push_back({eq, 0, i, i});
    term_runs_.back().end = i + 1;
    term_entries_.emplace_back(order[i], term_node_[order[i]]);
  }
  std::vector<Partial> sorted = partials_;
  std::stable_sort(sorted.begin(), sorted.end(), [](const Partial& a, const Partial& b) {
    return a.equation != b.equation ? a.equation < b.equation : a.var < b.var;
  });
  for (const Partial& p : sorted) {
    if (jacobian_runs_.empty() || jacobian_runs_.back().equation != p.equation ||
        jacobian_runs_.back().var != p.var) {
      const auto at = static_cast<std::uint32_t>(jacobian_entries_.size());
      jacobian_runs_.push_back({p.equation, p.var, at, at});
    }
    for (int k = 0; k < p.power; ++k) jacobian_entries_.emplace_back(p.term, p.node);
    jacobian_runs_.back().end = static_cast<std::uint32_t>(jacobian_entries_.size());
  }
}

namespace {

// Node values (re, im, im, re) from the product tree: child = parent · x_var.
void nodeValues(const CompiledShape& shape, const CVec& x, double* v) {
  const int n = shape.variables();
  Pair xa[kMaxVariables], xb[kMaxVariables], xc[kMaxVariables];
  for (int i = 0; i < n; ++i) {
    const double re = x[i].real(), im = x[i].imag();
    xa[i] = Pair{re, re};
    xb[i] = Pair{-im, im};
    xc[i] = Pair{im, -im};
  }
  const auto& nodes = shape.nodeList();
  storePair(v, Pair{1.0, 0.0});
  storePair(v + 2, Pair{0.0, 1.0});
  for (int k = 1; k < shape.nodes(); ++k) {
    const double* p = v + 4 * nodes[k].parent;
    const Pair z = loadPair(p), zs = loadPair(p + 2);
    const int var = nodes[k].var;
    storePair(v + 4 * k, mulPair(z, zs, xa[var], xb[var]));
    storePair(v + 4 * k + 2, xa[var] * zs + xc[var] * z);
  }
}

// An entry's coefficient pair (re, im) and its node's pair (re, im) and swap (im, re).
struct EntryValues {
  Pair k, m, ms;
};
inline EntryValues load(const CompiledShape::Entry* e, const char* k, const char* v) {
  const auto* m = reinterpret_cast<const double*>(v + e->node);
  return {loadPair(reinterpret_cast<const double*>(k + e->coefficient)), loadPair(m),
          loadPair(m + 2)};
}

// Σ k_e m_e over entries [e, end), k the coefficients, v the node values: two accumulator pairs
// (entries alternate between them) halve the chain of dependent adds. Inlined: the Jacobian's
// runs are short, a call for each was a tenth of its time.
inline __attribute__((always_inline)) Complex sum(const CompiledShape::Entry* e,
                                                  const CompiledShape::Entry* end, const double* k,
                                                  const double* v) {
  const char* kb = reinterpret_cast<const char*>(k);
  const char* vb = reinterpret_cast<const char*>(v);
  Pair a0{0.0, 0.0}, b0{0.0, 0.0}, a1{0.0, 0.0}, b1{0.0, 0.0};
  for (; end - e >= 2; e += 2) {
    const EntryValues x = load(e, kb, vb), y = load(e + 1, kb, vb);
    a0 += x.k * x.m;
    b0 += x.k * x.ms;
    a1 += y.k * y.m;
    b1 += y.k * y.ms;
  }
  if (e != end) {
    const EntryValues x = load(e, kb, vb);
    a0 += x.k * x.m;
    b0 += x.k * x.ms;
  }
  const Pair a = a0 + a1, b = b0 + b1;
  return Complex(a[0] - a[1], b[0] + b[1]);
}

// Both sums of one run over the same node values (f and fs: the node loads shared), two entries
// at a time as in sum().
void sum2(const CompiledShape::Entry* e, const CompiledShape::Entry* end, const double* k,
          const double* l, const double* v, Complex& fk, Complex& fl) {
  const char* kb = reinterpret_cast<const char*>(k);
  const char* lb = reinterpret_cast<const char*>(l);
  const char* vb = reinterpret_cast<const char*>(v);
  Pair a[2] = {}, b[2] = {}, c[2] = {}, d[2] = {};
  auto add = [&](const CompiledShape::Entry* x, int i) {
    const EntryValues w = load(x, kb, vb);
    const Pair ll = loadPair(reinterpret_cast<const double*>(lb + x->coefficient));
    a[i] += w.k * w.m;
    b[i] += w.k * w.ms;
    c[i] += ll * w.m;
    d[i] += ll * w.ms;
  };
  for (; end - e >= 2; e += 2) {
    add(e, 0);
    add(e + 1, 1);
  }
  if (e != end) add(e, 0);
  const Pair ka = a[0] + a[1], kb2 = b[0] + b[1], la = c[0] + c[1], lb2 = d[0] + d[1];
  fk = Complex(ka[0] - ka[1], kb2[0] + kb2[1]);
  fl = Complex(la[0] - la[1], lb2[0] + lb2[1]);
}

}  // namespace

void evaluate(const CompiledShape& shape, const Complex* c, const Complex* dc, const CVec& x,
              EvalScratch& scratch, CVec* f, CMat* J, CVec* fs) {
  const int n = shape.variables();
  double* v = scratch.values.data();
  nodeValues(shape, x, v);
  const double* cv = reinterpret_cast<const double*>(c);
  const double* dcv = reinterpret_cast<const double*>(dc);
  if (!dc) fs = nullptr;
  if (f) f->setZero(n);
  if (fs) fs->setZero(n);
  const CompiledShape::Entry* terms = shape.termEntries().data();
  for (const auto& run : shape.termRuns()) {
    const auto* b = terms + run.begin;
    const auto* e = terms + run.end;
    if (f && fs)
      sum2(b, e, cv, dcv, v, (*f)[run.equation], (*fs)[run.equation]);
    else if (f)
      (*f)[run.equation] = sum(b, e, cv, v);
    else if (fs)
      (*fs)[run.equation] = sum(b, e, dcv, v);
  }
  if (!J) return;
  J->setZero(n, n);
  const CompiledShape::Entry* partials = shape.jacobianEntries().data();
  for (const auto& run : shape.jacobianRuns())
    (*J)(run.equation, run.var) = sum(partials + run.begin, partials + run.end, cv, v);
}

}  // namespace relpos::complete::detail
