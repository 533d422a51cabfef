#pragma once
// Evaluates a Family's member through its public interface (shape + coefficients), as the engine
// does: what the encoding tests check the equations with.
#include <algorithm>
#include <complex>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete::test {

// Each equation's value divided by the sum of its terms' magnitudes: rounding makes it about
// 1e-16 at a root, whatever the root's size.
inline std::vector<Complex> evaluateMember(const Family& f, const std::vector<Complex>& params,
                                           const std::vector<Complex>& x) {
  const SystemShape& s = f.shape();
  std::vector<Complex> coeffs(s.terms.size());
  f.coefficients(params.data(), coeffs.data());
  std::vector<Complex> out(static_cast<std::size_t>(s.variables), 0.0);
  std::vector<double> size(out.size(), 0.0);
  for (std::size_t t = 0; t < s.terms.size(); ++t) {
    const Monomial& m = s.monomials[s.terms[t].monomial];
    Complex v = coeffs[t];
    for (int i = 0; i < m.degree; ++i) v *= x[m.vars[i]];
    out[s.terms[t].equation] += v;
    size[s.terms[t].equation] += std::abs(v);
  }
  for (std::size_t k = 0; k < out.size(); ++k) out[k] /= size[k] > 0.0 ? size[k] : 1.0;
  return out;
}

inline double maxAbs(const std::vector<Complex>& v) {
  double m = 0.0;
  for (const Complex& z : v) m = std::max(m, std::abs(z));
  return m;
}

inline std::vector<Complex> realMember(const std::vector<double>& p) {
  return std::vector<Complex>(p.begin(), p.end());
}

}  // namespace relpos::complete::test
