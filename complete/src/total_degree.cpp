#include "total_degree.hpp"

#include <cmath>

#include "homotopy.hpp"
#include "random.hpp"

namespace relpos::complete::detail {

std::uint64_t bezoutNumber(const CompiledShape& shape) {
  std::uint64_t b = 1;
  for (int d : shape.equationDegrees()) {
    if (d == 0) return 0;
    if (b > (std::uint64_t(1) << 62) / std::uint64_t(d)) return std::uint64_t(1) << 62;
    b *= std::uint64_t(d);
  }
  return b;
}

std::vector<CVec> totalDegreeEndpoints(const SystemShape& shape, const Complex* coefficients,
                                       std::uint64_t seed, std::int64_t* steps_left) {
  const CompiledShape target(shape);
  const int n = shape.variables;
  const std::vector<int>& degrees = target.equationDegrees();
  // The combined shape: F's terms, then x_k^{d_k} and 1 for every equation k.
  SystemShape combined = shape;
  const auto base_terms = static_cast<int>(shape.terms.size());
  const auto one = static_cast<std::uint16_t>(combined.monomials.size());
  combined.monomials.push_back(Monomial{});
  for (int k = 0; k < n; ++k) {
    Monomial power;
    power.degree = static_cast<std::uint8_t>(degrees[k]);
    for (int j = 0; j < degrees[k]; ++j) power.vars[j] = static_cast<std::uint8_t>(k);
    combined.monomials.push_back(power);
    combined.terms.push_back(
        {static_cast<std::uint16_t>(k), static_cast<std::uint16_t>(combined.monomials.size() - 1)});
    combined.terms.push_back({static_cast<std::uint16_t>(k), one});
  }
  const CompiledShape compiled(combined);
  const Complex gamma = randomGamma(seed);
  CoefficientPolynomials poly;
  poly.terms = static_cast<int>(combined.terms.size());
  poly.degree = 1;
  poly.a.assign(2 * static_cast<std::size_t>(poly.terms), Complex(0.0, 0.0));
  std::vector<Complex> end(poly.terms, Complex(0.0, 0.0));
  for (int t = 0; t < base_terms; ++t) {
    poly.a[2 * t + 1] = coefficients[t];  // s F
    end[t] = coefficients[t];
  }
  for (int k = 0; k < n; ++k) {  // (1 − s) γ (x_k^{d_k} − 1)
    const int t = base_terms + 2 * k;
    poly.a[2 * t] = gamma;
    poly.a[2 * t + 1] = -gamma;
    poly.a[2 * t + 2] = -gamma;
    poly.a[2 * t + 3] = gamma;
  }
  Tracker tracker(compiled, poly, Arc{}, end.data());
  std::vector<CVec> out;
  const std::uint64_t paths = bezoutNumber(target);
  std::vector<int> index(n, 0);
  for (std::uint64_t p = 0; p < paths; ++p) {
    CVec start(n);
    for (int k = 0; k < n; ++k)
      start[k] = std::polar(1.0, 6.283185307179586 * index[k] / degrees[k]);
    const PathEnd e = tracker.track(start);
    if (steps_left && (*steps_left -= e.steps) < 0) return out;
    if (e.status == PathStatus::kFinite) out.push_back(e.x);
    for (int k = 0; k < n && ++index[k] == degrees[k]; ++k) index[k] = 0;  // next combination
  }
  return out;
}

}  // namespace relpos::complete::detail
