#include "phc_systems.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

namespace relpos::bench {
namespace {

using C = std::complex<double>;
using Poly = std::map<std::vector<int>, C>;

struct Ring {
  int n;
  Poly var(int i) const {
    std::vector<int> e(n, 0);
    e[i] = 1;
    return {{e, C(1.0)}};
  }
  Poly constant(C c) const { return {{std::vector<int>(n, 0), c}}; }
};

Poly operator+(Poly a, const Poly& b) {
  for (const auto& [k, v] : b) a[k] += v;
  return a;
}
Poly operator*(C c, Poly a) {
  for (auto& kv : a) kv.second *= c;
  return a;
}
Poly operator-(const Poly& a, const Poly& b) { return a + C(-1.0) * b; }
Poly operator*(const Poly& a, const Poly& b) {
  Poly r;
  for (const auto& [ka, va] : a)
    for (const auto& [kb, vb] : b) {
      std::vector<int> k(ka.size());
      for (std::size_t i = 0; i < k.size(); ++i) k[i] = ka[i] + kb[i];
      r[k] += va * vb;
    }
  return r;
}
Poly chop(Poly a) {
  for (auto it = a.begin(); it != a.end();)
    it = std::abs(it->second) < 1e-14 ? a.erase(it) : std::next(it);
  return a;
}

using Q = std::array<Poly, 4>;  // a quaternion of polynomials (w, x, y, z)
Q qmul(const Q& a, const Q& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// The chart c·x = 1 with the prototype's coefficients (uniform in [0.5, 1.5], fixed seed): the
// same in the target and the start system, as a parameter homotopy needs.
Poly chart(const Ring& r, int first, int count) {
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(0.5, 1.5);
  Poly c = r.constant(-1.0);
  for (int i = 0; i < count; ++i) c = c + C(u(g)) * r.var(first + i);
  return c;
}

// Leg |e b − a e + 2 g|² − d²|e|² in Study parameters.
Poly leg(const Ring& r, const Vector3d& a, const Vector3d& b, C d2) {
  Q e, g, bq, aq;
  for (int i = 0; i < 4; ++i) e[i] = r.var(i), g[i] = r.var(4 + i);
  bq = {r.constant(0.0), r.constant(b.x()), r.constant(b.y()), r.constant(b.z())};
  aq = {r.constant(0.0), r.constant(a.x()), r.constant(a.y()), r.constant(a.z())};
  const Q eb = qmul(e, bq), ae = qmul(aq, e);
  Poly s, ee;
  for (int i = 0; i < 4; ++i) {
    const Poly v = eb[i] - ae[i] + C(2.0) * g[i];
    s = s + v * v;
    ee = ee + e[i] * e[i];
  }
  return chop(s - d2 * ee);
}

// The Study quadric e·g = 0, leg 1, legs 2..6 minus leg 1, the chart: the same shape for a target
// and the family's generic member.
PolySystem studySystem(const Ring& r, const std::vector<Poly>& legs) {
  PolySystem s;
  s.variables = {"q0", "q1", "q2", "q3", "h0", "h1", "h2", "h3"};
  Poly study;
  for (int i = 0; i < 4; ++i) study = study + r.var(i) * r.var(4 + i);
  s.equations.push_back(study);
  s.equations.push_back(legs[0]);
  for (std::size_t i = 1; i < legs.size(); ++i) s.equations.push_back(chop(legs[i] - legs[0]));
  s.equations.push_back(chart(r, 0, 4));
  return s;
}

PolySystem pointSystem(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b,
                       const std::vector<double>& d) {
  const Ring r{8};
  std::vector<Poly> legs;
  for (std::size_t i = 0; i < a.size(); ++i) legs.push_back(leg(r, a[i], b[i], d[i] * d[i]));
  return studySystem(r, legs);
}

std::array<Poly, 3> crossP(const std::array<Poly, 3>& u, const std::array<Poly, 3>& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Lines at distance r_i from c_i, any complex data (the generic member) or real.
PolySystem lineSystem(const std::vector<std::array<C, 3>>& c, const std::vector<C>& r2) {
  const Ring r{6};
  PolySystem s;
  s.variables = {"d1", "d2", "d3", "m1", "m2", "m3"};
  std::array<Poly, 3> d, m;
  for (int i = 0; i < 3; ++i) d[i] = r.var(i), m[i] = r.var(3 + i);
  s.equations.push_back(d[0] * m[0] + d[1] * m[1] + d[2] * m[2]);
  const Poly dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::array<Poly, 3> cp = {r.constant(c[k][0]), r.constant(c[k][1]), r.constant(c[k][2])};
    const std::array<Poly, 3> x = crossP(cp, d);
    Poly e;
    for (int i = 0; i < 3; ++i) e = e + (x[i] - m[i]) * (x[i] - m[i]);
    s.equations.push_back(chop(e - r2[k] * dd));
  }
  s.equations.push_back(chart(r, 0, 3));
  return s;
}

std::string number(C c, bool complex_form) {
  char buf[96];
  if (complex_form)
    std::snprintf(buf, sizeof buf, "(%+.16e %+.16e*i)", c.real(), c.imag());
  else
    std::snprintf(buf, sizeof buf, "%+.16e", c.real());
  return buf;
}

}  // namespace

bool familyOf(const Problem& p, Family* family) {
  bool points = p.constraints.size() == 6, lines = p.constraints.size() == 4;
  for (const InputConstraint& c : p.constraints) {
    const bool dist = c.type == "distance" && c.has_value && c.fixed.kind == FeatureKind::kPoint;
    points = points && dist && c.mobile.kind == FeatureKind::kPoint;
    lines = lines && dist && c.mobile.kind == FeatureKind::kLine;
  }
  if (points) *family = Family::kPointDistances;
  if (lines) *family = Family::kLineDistances;
  return points || lines;
}

PolySystem targetSystem(const Problem& p, Family family) {
  if (family == Family::kPointDistances) {
    std::vector<Vector3d> a, b;
    std::vector<double> d;
    for (const InputConstraint& c : p.constraints) {
      a.push_back(p.fixed.pose * c.fixed.point);
      b.push_back(c.mobile.point);
      d.push_back(c.value);
    }
    return pointSystem(a, b, d);
  }
  // Lines: the mobile line's own offset and direction do not enter; the solved line is mapped
  // back to a pose in poseOfSolution.
  std::vector<std::array<C, 3>> c;
  std::vector<C> r2;
  for (const InputConstraint& k : p.constraints) {
    const Vector3d w = p.fixed.pose * k.fixed.point;
    c.push_back({C(w.x()), C(w.y()), C(w.z())});
    r2.push_back(C(k.value * k.value));
  }
  return lineSystem(c, r2);
}

PolySystem genericMember(Family family, unsigned seed) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  auto crand = [&] { return C(n(g), n(g)); };
  if (family == Family::kLineDistances) {
    std::vector<std::array<C, 3>> c(4);
    std::vector<C> r2(4);
    for (int k = 0; k < 4; ++k) {
      c[k] = {crand(), crand(), crand()};
      r2[k] = crand();
    }
    return lineSystem(c, r2);
  }
  // Every point-distance system in Study parameters is e·g = 0, 4 g·g + gᵀA_i e + eᵀS_i e = 0
  // (A_i antisymmetric, S_i symmetric) after the chart: the generic member takes random complex
  // A_i, S_i (the prototype's make_family.py), a 40-root family.
  const Ring r{8};
  std::vector<Poly> legs;
  for (int l = 0; l < 6; ++l) {
    Poly L;
    for (int i = 0; i < 4; ++i) L = L + C(4.0) * (r.var(4 + i) * r.var(4 + i));
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j) {
        const C sij = crand();
        L = L + (i == j ? C(1.0) : C(2.0)) * sij * (r.var(i) * r.var(j));
        if (j > i) {
          const C aij = crand();
          L = L + aij * (r.var(4 + i) * r.var(j)) - aij * (r.var(4 + j) * r.var(i));
        }
      }
    legs.push_back(L);
  }
  return studySystem(r, legs);
}

std::string phcText(const PolySystem& s) {
  bool complex_form = false;
  for (const auto& e : s.equations)
    for (const auto& kv : e) complex_form = complex_form || kv.second.imag() != 0.0;
  std::string out =
      std::to_string(s.equations.size()) + " " + std::to_string(s.variables.size()) + "\n";
  for (const auto& e : s.equations) {
    std::string line;
    for (const auto& [k, v] : e) {
      std::string term = " + " + number(v, complex_form);
      for (std::size_t i = 0; i < k.size(); ++i)
        if (k[i] > 0) term += "*" + s.variables[i] + (k[i] > 1 ? "^" + std::to_string(k[i]) : "");
      if (line.size() + term.size() > 200) {
        out += line + "\n";
        line.clear();
      }
      line += term;
    }
    out += line + ";\n";
  }
  return out;
}

bool poseOfSolution(const Problem& p, Family family, const std::vector<double>& x, Isometry3d* X) {
  if (family == Family::kPointDistances) {
    const Quaterniond e(x[0], x[1], x[2], x[3]), g(x[4], x[5], x[6], x[7]);
    const double n2 = e.squaredNorm();
    if (!(n2 > 1e-300)) return false;
    const Quaterniond t = g * e.conjugate();
    *X = Isometry3d::Identity();
    X->linear() = e.normalized().toRotationMatrix();
    X->translation() = 2.0 * t.vec() / n2;
    return X->matrix().allFinite();
  }
  const Vector3d d(x[0], x[1], x[2]), m(x[3], x[4], x[5]);
  if (!(d.squaredNorm() > 1e-300)) return false;
  const Feature* line = nullptr;
  for (const InputConstraint& c : p.constraints)
    if (c.mobile.kind == FeatureKind::kLine) line = &c.mobile;
  if (!line) return false;
  // The pose turning the mobile line's direction onto d and its point onto the line's foot.
  const Vector3d u = d.normalized(), foot = d.cross(m) / d.squaredNorm();
  *X = Isometry3d::Identity();
  X->linear() = Quaterniond::FromTwoVectors(line->direction, u).toRotationMatrix();
  X->translation() = foot - X->linear() * line->point;
  return X->matrix().allFinite();
}

}  // namespace relpos::bench
