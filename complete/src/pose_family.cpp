// The pose encoding (encoding.hpp): Study parameters x = (e, g), one polynomial per
// PoseEquation, written once over the scalar type so that shape, coefficients and enclosures
// come from the same formulas.
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include "relpos/complete/encoding.hpp"

namespace relpos::complete {
namespace {

using K = PoseEquationKind;

template <typename S>
S dot3(const S* a, const S* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <typename S>
Poly<S> poseEquation(const PoseEquation& q, const S* p) {
  const Quat<S> e = variableQuat<S>(0), g = variableQuat<S>(4);
  const Quat<S> ec = conjugate(e);
  const Poly<S> ee = dot4(e, e);
  const S two(2.0);
  switch (q.kind) {
    case K::kChart: {
      Poly<S> f = Poly<S>::constant(S(-1.0));
      for (int i = 0; i < 4; ++i) f = f + p[q.value + i] * e[i];
      return f;
    }
    case K::kStudy:
      return dot4(e, g);
    case K::kNorm:
      return ee - Poly<S>::constant(S(1.0));
    case K::kPointPoint: {
      const Quat<S> v = e * pureQuat(p + q.mobile) - pureQuat(p + q.fixed) * e + two * g;
      return dot4(v, v) - p[q.value] * ee;
    }
    case K::kPointPlane: {
      const Quat<S> w = e * pureQuat(p + q.mobile) + two * g;
      return dotVec(p + q.fixed, w * ec) - p[q.value] * ee;
    }
    case K::kPlanePoint: {
      const Quat<S> w = pureQuat(p + q.fixed) * e - two * g;
      return dotVec(p + q.mobile, ec * w) - p[q.value] * ee;
    }
    case K::kPointLine:
    case K::kLinePoint: {
      const S* u = p + q.line;
      const S uu = dot3(u, u);
      const Quat<S> v = e * pureQuat(p + q.mobile) - pureQuat(p + q.fixed) * e + two * g;
      // (p − a)·u (e·e), read in the world (fixed line) or in the mobile frame (mobile line).
      const Poly<S> along = q.kind == K::kPointLine ? dotVec(u, v * ec) : dotVec(u, ec * v);
      return uu * (dot4(v, v) * ee) - along * along - (p[q.value] * uu) * (ee * ee);
    }
    case K::kDirection: {
      const Quat<S> turned = e * pureQuat(p + q.mobile) * ec;
      return dotVec(p + q.fixed, turned) - p[q.value] * ee;
    }
  }
  throw std::logic_error("unknown pose equation");
}

// "kind(fixed,mobile,line,value)" per equation: the offsets, assigned in order of first use by
// the encoder, spell out which equations share which features.
std::string signatureOf(const std::vector<PoseEquation>& eqs, int parameter_count) {
  std::string s = "pose/" + std::to_string(parameter_count);
  for (const PoseEquation& q : eqs)
    s += std::string(";") + toString(q.kind) + "(" + std::to_string(q.fixed) + "," +
         std::to_string(q.mobile) + "," + std::to_string(q.line) + "," + std::to_string(q.value) +
         ")";
  return s;
}

// Every slot the equations read (seedMember solves each value parameter from its equation).
std::vector<int> checkedValueParams(const std::vector<PoseEquation>& eqs, int n) {
  if (eqs.size() != 8) throw std::invalid_argument("a pose family has 8 equations");
  PolyFamily::ParameterUse use;
  for (const PoseEquation& q : eqs) {
    if (q.kind == K::kChart) {
      use.coordinates(q.value, 4);
      use.value(-1);
      continue;
    }
    const bool structural = q.kind == K::kStudy || q.kind == K::kNorm;
    use.value(structural ? -1 : q.value);
    if (structural) continue;
    use.coordinates(q.fixed, 3);
    use.coordinates(q.mobile, 3);
    if (q.kind == K::kPointLine || q.kind == K::kLinePoint) use.coordinates(q.line, 3);
    if (q.value < 0) throw std::invalid_argument("an equation without its value parameter");
  }
  return use.checked(n);
}

}  // namespace

const char* toString(PoseEquationKind k) {
  switch (k) {
    case K::kChart:
      return "chart";
    case K::kStudy:
      return "study";
    case K::kPointPoint:
      return "pp";
    case K::kPointPlane:
      return "pPl";
    case K::kPlanePoint:
      return "Plp";
    case K::kPointLine:
      return "pL";
    case K::kLinePoint:
      return "Lp";
    case K::kDirection:
      return "dir";
    case K::kNorm:
      return "norm";
  }
  return "?";
}

PoseFamily::PoseFamily(std::vector<PoseEquation> equations, int parameter_count)
    : equations_(std::move(equations)) {
  value_param_ = checkedValueParams(equations_, parameter_count);
  build(8, parameter_count, signatureOf(equations_, parameter_count));
}

template <typename S>
Poly<S> PoseFamily::equation(std::size_t k, const S* params) const {
  return poseEquation(equations_[k], params);
}
// The three passes PolyFamilyOf makes (other units see the declaration only).
template Poly<Structure> PoseFamily::equation(std::size_t, const Structure*) const;
template Poly<Complex> PoseFamily::equation(std::size_t, const Complex*) const;
template Poly<Interval> PoseFamily::equation(std::size_t, const Interval*) const;

// A random complex (e, g) on the chart and the Study quadric, random features, and the value
// parameters that make it a root.
void PoseFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < parameterCount(); ++i) params[i] = randomComplex(rng);
  Complex e[4], g[4];
  for (Complex& z : e) z = randomComplex(rng);
  for (Complex& z : g) z = randomComplex(rng);
  for (const PoseEquation& q : equations_) {
    Complex ce = 0.0;
    if (q.kind == K::kChart)
      for (int i = 0; i < 4; ++i) ce += params[q.value + i] * e[i];
    else if (q.kind == K::kNorm)
      ce = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] + e[3] * e[3]);
    else
      continue;
    for (Complex& z : e) z /= ce;
  }
  Complex eg = 0.0, ee = 0.0;
  for (int i = 0; i < 4; ++i) eg += e[i] * g[i], ee += e[i] * e[i];
  for (int i = 0; i < 4; ++i) {
    g[i] -= eg / ee * e[i];
    root[i] = e[i];
    root[4 + i] = g[i];
  }
  solveValueParameters(value_param_, params, root);
}

}  // namespace relpos::complete
