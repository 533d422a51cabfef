#include "real_root_proof.hpp"

#include <cmath>

#include "relpos/complete/encoding.hpp"
#include "translation_bound.hpp"

namespace relpos::complete::detail {
namespace {

// Room around the unit sphere's cube and the derived bounds: a root on the domain's face would
// never be inside a box of its own.
constexpr double kMargin = 1.0 / 16.0;

Vector3d vec3(const std::vector<double>& p, int at) { return {p[at], p[at + 1], p[at + 2]}; }

// Enclosures of the parameters of the exact problem: the normalised ones are a few roundings of
// numbers of size about 1 away from it (normalisationOf centres and scales the geometry).
std::vector<Interval> parameterEnclosures(const std::vector<double>& target) {
  std::vector<Interval> p;
  for (double v : target) p.push_back(Interval(v) + Interval(-1e-14, 1e-14) * (1.0 + std::abs(v)));
  return p;
}

RealBox boxOf(const Interval* x, int n) {
  RealBox b;
  b.lo.resize(n);
  b.hi.resize(n);
  for (int i = 0; i < n; ++i) b.lo[i] = x[i].lower(), b.hi[i] = x[i].upper();
  return b;
}

// What a bound that is not a box proves: nothing (unbounded), or that no root exists (empty).
ExclusionResult unboxed(Bound b, const std::string& what) {
  ExclusionResult r;
  r.proven = b == Bound::kEmpty;  // no real root at all: every one (none) is known
  if (!r.proven) r.why = "the constraints do not bound the " + what;
  return r;
}

// The variables from `first_secondary` on (a translation, a foot) are solved for given the
// others (a rotation, a direction).
ExclusionResult prove(const Family& family, const std::vector<double>& target,
                      const RealBox& domain, const std::vector<RealBox>& known, int first_secondary,
                      const std::vector<int>& negated, const ExclusionOptions& options) {
  const std::vector<Interval> params = parameterEnclosures(target);
  std::vector<Interval> coefficients(family.shape().terms.size());
  family.coefficients(params.data(), coefficients.data());
  std::vector<bool> secondary(family.shape().variables, false);
  for (std::size_t i = first_secondary; i < secondary.size(); ++i) secondary[i] = true;
  return excludeUnknownRoots(family.shape(), coefficients.data(), domain, known, secondary, negated,
                             options);
}

// The slabs that bound the translation of a pose, from the equations that bound it (at e·e = 1:
// p = R b + t).
std::vector<Slab> translationSlabs(const PoseEncoding& enc) {
  using K = PoseEquationKind;
  const std::vector<double>& p = enc.target;
  std::vector<Slab> slabs;
  for (const PoseEquation& q : enc.equations) {
    if (q.kind == K::kPointPoint) {  // |t + R b − a| = √D
      const double d = std::sqrt(std::max(0.0, p[q.value]));
      ballSlabs(vec3(p, q.fixed), vec3(p, q.mobile).norm() + d, &slabs);
    } else if (q.kind == K::kPointPlane) {  // n·(R b + t) = h
      const Vector3d n = vec3(p, q.fixed);
      const double reach = n.norm() * vec3(p, q.mobile).norm();
      slabs.push_back({n, p[q.value] - reach, p[q.value] + reach, -1});
    } else if (q.kind == K::kPointLine) {  // |(t + R b − a) × û| = √D
      Vector3d u = vec3(p, q.line), n1, n2;
      if (!(u.norm() > 0.0)) continue;
      u.normalize();
      const Vector3d a = vec3(p, q.fixed);
      const double reach = vec3(p, q.mobile).norm() + std::sqrt(std::max(0.0, p[q.value]));
      n1 = u.unitOrthogonal();
      n2 = u.cross(n1);
      for (const Vector3d& n : {n1, n2})
        slabs.push_back({n, n.dot(a) - reach, n.dot(a) + reach, -1});
    }
  }
  return slabs;
}

}  // namespace

ExclusionResult proveRootsKnown(const PoseEncoding& enc, const std::vector<CertifiedRoot>& roots,
                                const ExclusionOptions& options) {
  using K = PoseEquationKind;
  Vector3d lo, hi;
  const Bound bound = boundingBox(translationSlabs(enc), kMargin, &lo, &hi);
  if (bound != Bound::kBox) return unboxed(bound, "translation");
  // |g| = |t| / 2 at e·e = 1, in each coordinate.
  double tt = 0.0;
  for (int i = 0; i < 3; ++i) tt += std::max(lo[i] * lo[i], hi[i] * hi[i]);
  const double G = 0.5 * std::sqrt(tt) * (1.0 + 1e-12) + kMargin;
  RealBox domain;
  domain.lo.resize(8);
  domain.hi.resize(8);
  for (int i = 0; i < 4; ++i) {
    domain.lo[i] = i == 0 ? -kMargin : -1.0 - kMargin;
    domain.hi[i] = 1.0 + kMargin;
    domain.lo[4 + i] = -G;
    domain.hi[4 + i] = G;
  }
  // The real roots in the e·e = 1 chart, both signs: (e, g) / |e| from the certified box.
  std::vector<RealBox> known;
  for (const CertifiedRoot& r : roots) {
    if (!r.real || r.x.size() != 8) continue;
    Interval x[8];
    for (int i = 0; i < 8; ++i) x[i] = Interval(r.x[i].real()) + Interval(-r.radius, r.radius);
    const Interval ee = square(x[0]) + square(x[1]) + square(x[2]) + square(x[3]);
    if (!(ee.lower() > 0.0)) continue;  // no pose: the proof will not account for it
    const Interval norm = sqrt(ee);
    Interval unit[8], opposite[8];
    for (int i = 0; i < 8; ++i) unit[i] = x[i] / norm, opposite[i] = -unit[i];
    known.push_back(boxOf(unit, 8));
    known.push_back(boxOf(opposite, 8));
  }
  std::vector<PoseEquation> eqs = enc.equations;
  for (PoseEquation& q : eqs)
    if (q.kind == K::kChart) q = {K::kNorm, -1, -1, -1, -1};
  const PoseFamily real(eqs, static_cast<int>(enc.target.size()));
  return prove(real, enc.target, domain, known, 4, {}, options);
}

ExclusionResult proveRootsKnown(const LineEncoding& enc, const std::vector<CertifiedRoot>& roots,
                                const ExclusionOptions& options) {
  using K = LineEquationKind;
  const std::vector<double>& p = enc.target;
  std::vector<Slab> slabs;
  for (const LineEquation& q : enc.equations) {
    if (q.kind == K::kPointDistance)  // the line within √D of the point: its foot within |p| + √D
      ballSlabs(Vector3d::Zero(), vec3(p, q.fixed).norm() + std::sqrt(std::max(0.0, p[q.value])),
                &slabs);
    else if (q.kind == K::kPlaneOffset)  // n·q = h
      slabs.push_back({vec3(p, q.fixed), p[q.value], p[q.value], -1});
  }
  Vector3d lo, hi;
  const Bound bound = boundingBox(slabs, kMargin, &lo, &hi);
  if (bound != Bound::kBox) return unboxed(bound, "line");
  // (w, q) ↦ (−w, q) maps roots to roots when no equation tells the two directions apart (no
  // angle but right angles): half the directions, w₀ ≥ 0, then suffice.
  bool symmetric = true;
  for (const LineEquation& q : enc.equations)
    symmetric = symmetric && (q.kind != K::kDirection || p[q.value] == 0.0);
  RealBox domain;
  domain.lo.resize(6);
  domain.hi.resize(6);
  for (int i = 0; i < 3; ++i) {
    domain.lo[i] = i == 0 && symmetric ? -kMargin : -1.0 - kMargin;
    domain.hi[i] = 1.0 + kMargin;
    domain.lo[3 + i] = lo[i];
    domain.hi[3 + i] = hi[i];
  }
  std::vector<RealBox> known;
  for (const CertifiedRoot& r : roots) {
    if (!r.real || r.x.size() != 6) continue;
    Interval x[6];
    for (int i = 0; i < 6; ++i) x[i] = Interval(r.x[i].real()) + Interval(-r.radius, r.radius);
    known.push_back(boxOf(x, 6));
  }
  const LineFamily family(enc.equations, static_cast<int>(p.size()));
  std::vector<int> negated;
  if (symmetric) negated = {0, 1, 2};
  return prove(family, p, domain, known, 3, negated, options);
}

}  // namespace relpos::complete::detail
