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

template <typename S>
void allPoseEquations(const std::vector<PoseEquation>& eqs, const S* p, std::vector<Poly<S>>& out) {
  out.clear();
  for (const PoseEquation& q : eqs) out.push_back(poseEquation(q, p));
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

// Checks the slots: in range, and each value parameter in one equation only and never a
// coordinate (seedMember solves it from that equation alone).
std::vector<int> checkedValueParams(const std::vector<PoseEquation>& eqs, int n) {
  if (eqs.size() != 8) throw std::invalid_argument("a pose family has 8 equations");
  std::set<int> coordinates, values;
  std::vector<int> value_param;
  auto slot = [&](int offset, int width, bool needed) {
    if (offset < 0 && !needed) return;
    if (offset < 0 || offset + width > n)
      throw std::invalid_argument("parameter slot out of range");
    for (int i = 0; i < width; ++i) coordinates.insert(offset + i);
  };
  for (const PoseEquation& q : eqs) {
    const bool points = q.kind != K::kChart && q.kind != K::kStudy;
    slot(q.fixed, 3, points);
    slot(q.mobile, 3, points);
    slot(q.line, 3, q.kind == K::kPointLine || q.kind == K::kLinePoint);
    if (q.kind == K::kChart) {
      slot(q.value, 4, true);
      value_param.push_back(-1);
      continue;
    }
    if (q.kind == K::kStudy) {
      value_param.push_back(-1);
      continue;
    }
    if (q.value < 0 || q.value >= n || !values.insert(q.value).second)
      throw std::invalid_argument("a value parameter must belong to one equation");
    value_param.push_back(q.value);
  }
  for (int v : values)
    if (coordinates.count(v)) throw std::invalid_argument("a value parameter used as a coordinate");
  return value_param;
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
  }
  return "?";
}

PoseFamily::PoseFamily(std::vector<PoseEquation> equations, int parameter_count)
    : equations_(std::move(equations)) {
  value_param_ = checkedValueParams(equations_, parameter_count);
  build(8, parameter_count, signatureOf(equations_, parameter_count));
}

void PoseFamily::equations(const Structure* p, std::vector<Poly<Structure>>& out) const {
  allPoseEquations(equations_, p, out);
}
void PoseFamily::equations(const Complex* p, std::vector<Poly<Complex>>& out) const {
  allPoseEquations(equations_, p, out);
}
void PoseFamily::equations(const Interval* p, std::vector<Poly<Interval>>& out) const {
  allPoseEquations(equations_, p, out);
}

// A random complex (e, g) on the chart and the Study quadric, random features, and the value
// parameters that make it a root.
void PoseFamily::seedMember(std::uint64_t seed, Complex* params, Complex* root) const {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < parameterCount(); ++i) params[i] = randomComplex(rng);
  Complex e[4], g[4];
  for (Complex& z : e) z = randomComplex(rng);
  for (Complex& z : g) z = randomComplex(rng);
  for (const PoseEquation& q : equations_) {
    if (q.kind != K::kChart) continue;
    Complex ce = 0.0;
    for (int i = 0; i < 4; ++i) ce += params[q.value + i] * e[i];
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
