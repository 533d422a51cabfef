// The line encoding (encoding.hpp): x = (w, q), the world direction of the mobile line and its
// foot (the point nearest the origin), with w·w = 1 and q·w = 0 among the equations.
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "relpos/complete/encoding.hpp"

namespace relpos::complete {
namespace {

using K = LineEquationKind;

template <typename S>
Poly<S> lineEquation(const LineEquation& q, const S* p) {
  Poly<S> w[3], x[3];
  for (int i = 0; i < 3; ++i) w[i] = Poly<S>::variable(i), x[i] = Poly<S>::variable(3 + i);
  auto dotConst = [&](const S* c, const Poly<S>* v) {
    return c[0] * v[0] + c[1] * v[1] + c[2] * v[2];
  };
  switch (q.kind) {
    case K::kUnit:
      return w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - Poly<S>::constant(S(1.0));
    case K::kFoot:
      return x[0] * w[0] + x[1] * w[1] + x[2] * w[2];
    case K::kPointDistance: {
      // |p − q|² − (p·w)² − D, with (p − q)·w = p·w on the foot.
      const S* pt = p + q.fixed;
      Poly<S> sum = Poly<S>::constant(pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2] - p[q.value]);
      for (int i = 0; i < 3; ++i) sum = sum + x[i] * x[i] - (S(2.0) * pt[i]) * x[i];
      const Poly<S> along = dotConst(pt, w);
      return sum - along * along;
    }
    case K::kDirection:
      return dotConst(p + q.fixed, w) - Poly<S>::constant(p[q.value]);
    case K::kPlaneOffset:
      return dotConst(p + q.fixed, x) - Poly<S>::constant(p[q.value]);
  }
  throw std::logic_error("unknown line equation");
}

std::string signatureOf(const std::vector<LineEquation>& eqs, int parameter_count) {
  std::string s = "line/" + std::to_string(parameter_count);
  for (const LineEquation& q : eqs)
    s += std::string(";") + toString(q.kind) + "(" + std::to_string(q.fixed) + "," +
         std::to_string(q.value) + ")";
  return s;
}

std::vector<int> checkedValueParams(const std::vector<LineEquation>& eqs, int n) {
  if (eqs.size() != 6) throw std::invalid_argument("a line family has 6 equations");
  PolyFamily::ParameterUse use;
  for (const LineEquation& q : eqs) {
    const bool structural = q.kind == K::kUnit || q.kind == K::kFoot;
    use.value(structural ? -1 : q.value);
    if (structural) continue;
    use.coordinates(q.fixed, 3);
    if (q.value < 0) throw std::invalid_argument("an equation without its value parameter");
  }
  return use.checked(n);
}

}  // namespace

const char* toString(LineEquationKind k) {
  switch (k) {
    case K::kUnit:
      return "unit";
    case K::kFoot:
      return "foot";
    case K::kPointDistance:
      return "pL";
    case K::kDirection:
      return "dir";
    case K::kPlaneOffset:
      return "Pl";
  }
  return "?";
}

LineFamily::LineFamily(std::vector<LineEquation> equations, int parameter_count)
    : equations_(std::move(equations)) {
  value_param_ = checkedValueParams(equations_, parameter_count);
  build(6, parameter_count, signatureOf(equations_, parameter_count));
}

template <typename S>
Poly<S> LineFamily::equation(std::size_t k, const S* params) const {
  return lineEquation(equations_[k], params);
}
// The three passes PolyFamilyOf makes (other units see the declaration only).
template Poly<Structure> LineFamily::equation(std::size_t, const Structure*) const;
template Poly<Complex> LineFamily::equation(std::size_t, const Complex*) const;
template Poly<Interval> LineFamily::equation(std::size_t, const Interval*) const;

// A random complex unit direction, a foot orthogonal to it, random features, and the values.
void LineFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < parameterCount(); ++i) params[i] = randomComplex(rng);
  Complex w[3], q[3];
  for (Complex& z : w) z = randomComplex(rng);
  for (Complex& z : q) z = randomComplex(rng);
  const Complex n = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  for (Complex& z : w) z /= n;
  const Complex qw = q[0] * w[0] + q[1] * w[1] + q[2] * w[2];
  for (int i = 0; i < 3; ++i) {
    q[i] -= qw * w[i];
    root[i] = w[i];
    root[3 + i] = q[i];
  }
  solveValueParameters(value_param_, params, root);
}

}  // namespace relpos::complete
