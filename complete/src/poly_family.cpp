#include "relpos/complete/poly_family.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

namespace relpos::complete {

void PolyFamily::build(int variables, int parameter_count, std::string signature) {
  if (variables > kMaxVariables) throw std::logic_error("too many unknowns for a family");
  signature_ = std::move(signature);
  parameter_count_ = parameter_count;
  std::vector<Structure> p(static_cast<std::size_t>(parameter_count), Structure::parameter());
  std::vector<Poly<Structure>> eqs;
  equations(p.data(), eqs);
  if (static_cast<int>(eqs.size()) != variables)
    throw std::logic_error("a family must be square: as many equations as unknowns");
  shape_ = SystemShape{};
  shape_.variables = variables;
  keys_.assign(eqs.size(), {});
  first_term_.assign(eqs.size(), 0);
  std::map<MonomialKey, int> monomial_index;
  coefficient_degree_ = 0;
  for (std::size_t k = 0; k < eqs.size(); ++k) {
    first_term_[k] = static_cast<int>(shape_.terms.size());
    for (const auto& [key, s] : eqs[k].terms) {
      if (s.degree < 0) continue;  // never reached: no equation builds a zero constant
      coefficient_degree_ = std::max(coefficient_degree_, s.degree);
      auto it = monomial_index.find(key);
      if (it == monomial_index.end()) {
        it = monomial_index.emplace(key, static_cast<int>(shape_.monomials.size())).first;
        shape_.monomials.push_back(monomialOf(key));
      }
      keys_[k].push_back(key);
      shape_.terms.push_back(
          {static_cast<std::uint16_t>(k), static_cast<std::uint16_t>(it->second)});
    }
  }
}

template <typename S>
void PolyFamily::scatter(const std::vector<Poly<S>>& eqs, S* coeffs) const {
  for (std::size_t t = 0; t < shape_.terms.size(); ++t) coeffs[t] = S(0.0);
  for (std::size_t k = 0; k < eqs.size(); ++k) {
    const std::vector<MonomialKey>& keys = keys_[k];
    for (const auto& [key, c] : eqs[k].terms) {
      const auto it = std::lower_bound(keys.begin(), keys.end(), key);
      if (it == keys.end() || *it != key) throw std::logic_error("a term outside the shape");
      coeffs[first_term_[k] + (it - keys.begin())] = c;
    }
  }
}

void PolyFamily::coefficients(const Complex* params, Complex* coeffs) const {
  std::vector<Poly<Complex>> eqs;
  equations(params, eqs);
  scatter(eqs, coeffs);
}

void PolyFamily::coefficients(const Interval* params, Interval* coeffs) const {
  std::vector<Poly<Interval>> eqs;
  equations(params, eqs);
  scatter(eqs, coeffs);
}

std::vector<Poly<Complex>> PolyFamily::equationsAt(const Complex* params) const {
  std::vector<Poly<Complex>> eqs;
  equations(params, eqs);
  return eqs;
}

void PolyFamily::ParameterUse::coordinates(int offset, int width) {
  slots_.push_back({offset, width});
}

std::vector<int> PolyFamily::ParameterUse::checked(int parameter_count) const {
  std::set<int> coordinates, values;
  for (const auto& [offset, width] : slots_) {
    if (offset < 0 || offset + width > parameter_count)
      throw std::invalid_argument("parameter slot out of range");
    for (int i = 0; i < width; ++i) coordinates.insert(offset + i);
  }
  for (int v : values_) {
    if (v < 0) continue;
    if (v >= parameter_count || !values.insert(v).second)
      throw std::invalid_argument("a value parameter must belong to one equation");
    if (coordinates.count(v)) throw std::invalid_argument("a value parameter used as a coordinate");
  }
  return values_;
}

Complex PolyFamily::randomComplex(std::mt19937_64& rng) {
  auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1p-52 - 1.0; };
  const double re = uniform();
  return {re, uniform()};
}

// Equation k is f0 + λ·(f1 − f0) in its value parameter λ (f0, f1: its values at the root for
// λ = 0 and λ = 1), so λ = −f0 / (f1 − f0).
void PolyFamily::solveValueParameters(const std::vector<int>& value_param, Complex* params,
                                      const Complex* root) const {
  for (std::size_t k = 0; k < value_param.size(); ++k) {
    const int v = value_param[k];
    if (v < 0) continue;
    params[v] = 0.0;
    const Complex f0 = evaluate(equationsAt(params)[k], root);
    params[v] = 1.0;
    const Complex f1 = evaluate(equationsAt(params)[k], root);
    params[v] = -f0 / (f1 - f0);
  }
}

}  // namespace relpos::complete
