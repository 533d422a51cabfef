// traceTest (trace_test.hpp): the curve over a general line of the affine parameter subspace, a
// witness set of it filled by monodromy on the slicing hyperplane, the trace along a parallel
// pencil, and the fibre recovered from the witness set.
#include "trace_test.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "homotopy.hpp"
#include "krawczyk.hpp"
#include "polynomial_eval.hpp"
#include "random.hpp"

namespace relpos::complete::detail {
namespace {

constexpr int kMaxLoops = 60;
constexpr int kStaleLoops = 12;
constexpr double kTraceTolerance = 1e-7;
constexpr int kAttempts = 8;

// The curve {(x, t) : Σ (c0 + t c1) m(x) = 0} cut by the hyperplane λ·(x, t) = s; parameters
// (λ_0..λ_n, s). Only complex coefficients: it is tracked and certified as a complex system.
class SliceFamily final : public Family {
 public:
  SliceFamily(const SystemShape& base, const std::vector<Complex>& c0,
              const std::vector<Complex>& c1) {
    const int n = base.variables;
    shape_.variables = n + 1;
    auto monomial = [&](Monomial m) {
      for (std::size_t i = 0; i < shape_.monomials.size(); ++i)
        if (shape_.monomials[i] == m) return static_cast<std::uint16_t>(i);
      shape_.monomials.push_back(m);
      return static_cast<std::uint16_t>(shape_.monomials.size() - 1);
    };
    for (std::size_t t = 0; t < base.terms.size(); ++t) {
      const Monomial& m = base.monomials[base.terms[t].monomial];
      shape_.terms.push_back({base.terms[t].equation, monomial(m)});
      fixed_.push_back(c0[t]);
      if (c1[t] == Complex(0.0, 0.0)) continue;
      if (m.degree >= kMaxMonomialDegree)
        throw std::invalid_argument("a monomial of degree " + std::to_string(m.degree) +
                                    " has a coefficient that moves along the line");
      Monomial mt = m;
      mt.vars[mt.degree++] = static_cast<std::uint8_t>(n);  // t: the last variable
      shape_.terms.push_back({base.terms[t].equation, monomial(mt)});
      fixed_.push_back(c1[t]);
    }
    for (int j = 0; j <= n; ++j) {
      Monomial m;
      m.degree = 1;
      m.vars[0] = static_cast<std::uint8_t>(j);
      shape_.terms.push_back({static_cast<std::uint16_t>(n), monomial(m)});
    }
    shape_.terms.push_back({static_cast<std::uint16_t>(n), monomial(Monomial{})});
  }
  const std::string& signature() const override { return signature_; }
  const SystemShape& shape() const override { return shape_; }
  int parameterCount() const override { return shape_.variables + 1; }
  int coefficientDegree() const override { return 1; }
  void coefficients(const Complex* q, Complex* out) const override {
    std::copy(fixed_.begin(), fixed_.end(), out);
    const int k = static_cast<int>(fixed_.size()), m = shape_.variables;
    for (int j = 0; j < m; ++j) out[k + j] = q[j];
    out[k + m] = -q[m];
  }
  void coefficients(const Interval*, Interval* out) const override {
    // Not a real family: no enclosure (never used; whole intervals prove nothing).
    for (std::size_t t = 0; t < shape_.terms.size(); ++t) out[t] = Interval::whole();
  }
  void seedMember(std::uint64_t, Complex*, Complex*) const override {
    throw std::logic_error("the slice family has no seed member");
  }

 private:
  std::string signature_ = "slice";
  SystemShape shape_;
  std::vector<Complex> fixed_;
};

// Endpoints (with status) of the paths from `starts` at q0 to q1 along the arc γ.
std::vector<PathEnd> track(const Family& f, const CompiledShape& shape,
                           const std::vector<Complex>& q0, const std::vector<Complex>& q1,
                           Complex gamma, const std::vector<CVec>& starts) {
  const CoefficientPolynomials poly = interpolateSegment(f, q0.data(), q1.data());
  std::vector<Complex> end(shape.terms());
  f.coefficients(q1.data(), end.data());
  Tracker tracker(shape, poly, Arc{gamma}, end.data());
  std::vector<PathEnd> out;
  for (const CVec& s : starts) out.push_back(tracker.track(s));
  return out;
}

// Distinct certified points of one member (boxes pairwise disjoint).
class PointSet {
 public:
  PointSet(const CompiledShape& shape, std::vector<Complex> c)
      : shape_(shape), c_(std::move(c)), cert_(shape, c_.data()), scratch_(shape) {}
  // 1: added, 0: a known point, -1: not certified.
  int add(CVec x) {
    if (polish(shape_, c_.data(), x, scratch_, 6) < 0.0) return -1;
    BoxCertificate b = cert_.certify(x);
    if (!b.ok) return -1;
    for (const BoxCertificate& k : boxes_)
      if (boxesOverlap(k.x, k.radius, b.x, b.radius)) return 0;
    boxes_.push_back(std::move(b));
    return 1;
  }
  std::vector<CVec> points() const {
    std::vector<CVec> out;
    for (const auto& b : boxes_) out.push_back(b.x);
    return out;
  }
  std::size_t size() const { return boxes_.size(); }

 private:
  const CompiledShape& shape_;
  std::vector<Complex> c_;
  Certifier cert_;
  EvalScratch scratch_;
  std::vector<BoxCertificate> boxes_;
};

// Whether the coefficients are affine along direction d at p (second difference ~ 0) and move.
bool affineAlong(const Family& f, const std::vector<Complex>& p, const std::vector<Complex>& d,
                 bool* moves) {
  const int terms = static_cast<int>(f.shape().terms.size());
  std::vector<Complex> q(p), c0(terms), c1(terms), c2(terms);
  f.coefficients(q.data(), c0.data());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = p[i] + d[i];
  f.coefficients(q.data(), c1.data());
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = p[i] + 2.0 * d[i];
  f.coefficients(q.data(), c2.data());
  double scale = 0.0, second = 0.0, first = 0.0;
  for (int t = 0; t < terms; ++t) {
    scale = std::max({scale, std::abs(c0[t]), std::abs(c1[t]), std::abs(c2[t])});
    second = std::max(second, std::abs(c2[t] - 2.0 * c1[t] + c0[t]));
    first = std::max(first, std::abs(c1[t] - c0[t]));
  }
  *moves = first > 1e-12 * (1.0 + scale);
  return second <= 1e-11 * (1.0 + scale);
}

// One attempt: its own line, slices and loops from `seed`.
TraceOutcome traceOnce(const Family& f, const StartSystem& s, std::uint64_t seed) {
  TraceOutcome out;
  auto fail = [&](std::string why) {
    out.why = std::move(why);
    return out;
  };
  const SystemShape& base = f.shape();
  const CompiledShape shape(base);
  const int n = shape.variables(), np = f.parameterCount(), terms = shape.terms();
  if (s.roots.empty() || static_cast<int>(s.params.size()) != np) return fail("no start system");
  SplitMix64 rng(seed);
  double scale = 0.0;
  for (const Complex& p : s.params) scale += std::norm(p);
  scale = np > 0 ? std::sqrt(scale / np) : 1.0;
  if (!(scale > 0.0)) scale = 1.0;

  // S: the parameters the coefficients are jointly affine in (greedy, along random directions).
  std::vector<Complex> dir(np, Complex(0.0, 0.0));
  std::vector<int> affine;
  for (int k = 0; k < np; ++k) {
    std::vector<Complex> trial = dir;
    trial[k] = scale * rng.complexGaussian();
    bool moves = false;
    if (!affineAlong(f, s.params, trial, &moves) || !moves) continue;
    dir = trial;
    affine.push_back(k);
  }
  out.affine_parameters = static_cast<int>(affine.size());
  if (affine.size() < 2) return fail("fewer than two parameters enter affinely");
  // A general line of S: p_L + t d.
  auto randomInS = [&] {
    std::vector<Complex> v(np, Complex(0.0, 0.0));
    for (int k : affine) v[k] = scale * rng.complexGaussian();
    return v;
  };
  std::vector<Complex> pL = s.params, d = randomInS();
  {
    const std::vector<Complex> shift = randomInS();
    for (int i = 0; i < np; ++i) pL[i] += 0.5 * shift[i];
  }
  std::vector<Complex> cL(terms), c1(terms), q(np);
  f.coefficients(pL.data(), cL.data());
  for (int i = 0; i < np; ++i) q[i] = pL[i] + d[i];
  f.coefficients(q.data(), c1.data());
  for (int t = 0; t < terms; ++t) {
    c1[t] -= cL[t];
    if (std::abs(c1[t]) <= 1e-13 * (1.0 + std::abs(cL[t]))) c1[t] = Complex(0.0, 0.0);
  }

  // The start roots at p_L.
  PointSet moved(shape, cL);
  {
    std::vector<CVec> starts;
    for (const auto& r : s.roots) starts.push_back(CVec(r));
    for (const PathEnd& e : track(f, shape, s.params, pL, Complex(1.0, 0.0), starts))
      if (e.status == PathStatus::kFinite) moved.add(e.x);
    if (moved.size() != s.roots.size()) return fail("the start roots did not all move to p_L");
  }

  std::unique_ptr<SliceFamily> slice;
  try {
    slice = std::make_unique<SliceFamily>(base, cL, c1);
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  const CompiledShape yshape(slice->shape());
  const int m = n + 1;
  // q = (λ, s): the fibre slice t = 0, and a general slice.
  std::vector<Complex> qA(m + 1, Complex(0.0, 0.0)), qB(m + 1);
  qA[n] = 1.0;
  auto randomSlice = [&] {
    std::vector<Complex> v(m + 1);
    for (auto& z : v) z = rng.complexGaussian();
    return v;
  };
  qB = randomSlice();
  std::vector<Complex> cB(yshape.terms());
  slice->coefficients(qB.data(), cB.data());
  PointSet W(yshape, cB);
  std::vector<CVec> fibre;
  for (const CVec& x : moved.points()) {
    CVec y(m);
    y.head(n) = x;
    y[n] = 0.0;
    fibre.push_back(y);
  }
  for (const PathEnd& e : track(*slice, yshape, qA, qB, randomGamma(rng.next()), fibre))
    if (e.status == PathStatus::kFinite) W.add(e.x);

  // The trace Σ μ·y over W at s_B + δ for δ = 0, δ1, δ2; affine iff the two slopes agree.
  std::vector<Complex> mu(m);
  for (auto& z : mu) z = rng.complexGaussian();
  const Complex delta1 = rng.complexGaussian(), delta2 = rng.complexGaussian();
  auto traceResidual = [&](const std::vector<CVec>& pts) {
    Complex tr[3];
    double size = 0.0;
    const Complex deltas[3] = {0.0, delta1, delta2};
    for (int k = 0; k < 3; ++k) {
      std::vector<Complex> qk = qB;
      qk[m] += deltas[k];
      std::vector<Complex> ck(yshape.terms());
      slice->coefficients(qk.data(), ck.data());
      std::vector<CVec> ends;
      if (k == 0) {
        ends = pts;
      } else {
        for (const PathEnd& e : track(*slice, yshape, qB, qk, Complex(1.0, 0.0), pts)) {
          if (e.status != PathStatus::kFinite) return -1.0;
          ends.push_back(e.x);
        }
      }
      // The moved points must be distinct certified points of that slice (no path jumped).
      PointSet check(yshape, ck);
      tr[k] = 0.0;
      for (const CVec& y : ends) {
        if (check.add(y) != 1) return -1.0;
        for (int j = 0; j < m; ++j) tr[k] += mu[j] * y[j];
        size += normInf(y);
      }
    }
    const Complex slope1 = (tr[1] - tr[0]) / delta1, slope2 = (tr[2] - tr[0]) / delta2;
    return std::abs(slope1 - slope2) / (1.0 + size);
  };

  int stale = 0, lost = 0, uncertified = 0;
  double residual = traceResidual(W.points());
  while (!(residual >= 0.0 && residual <= kTraceTolerance)) {
    if (out.loops >= kMaxLoops || stale >= kStaleLoops) {
      out.witness_points = static_cast<int>(W.size());
      out.trace_residual = residual;
      return fail("the trace did not become affine (" + std::to_string(W.size()) +
                  " witness points, " + std::to_string(out.loops) + " loops, residual " +
                  std::to_string(residual) + ", " + std::to_string(lost) + " paths lost, " +
                  std::to_string(uncertified) + " endpoints not certified)");
    }
    ++out.loops;
    const std::vector<Complex> r1 = randomSlice(), r2 = randomSlice();
    std::vector<CVec> y = W.points(), next;
    using Leg = std::pair<const std::vector<Complex>*, const std::vector<Complex>*>;
    for (const Leg& leg : {Leg(&qB, &r1), Leg(&r1, &r2), Leg(&r2, &qB)}) {
      next.clear();
      for (const PathEnd& e : track(*slice, yshape, *leg.first, *leg.second, 1.0, y))
        if (e.status == PathStatus::kFinite)
          next.push_back(e.x);
        else
          ++lost;
      y = next;
    }
    int added = 0;
    for (const CVec& e : y) {
      const int a = W.add(e);
      added += a == 1 ? 1 : 0;
      uncertified += a < 0 ? 1 : 0;
    }
    stale = added == 0 ? stale + 1 : 0;
    if (added > 0 || residual < 0.0) residual = traceResidual(W.points());
  }
  out.witness_points = static_cast<int>(W.size());
  out.trace_residual = residual;

  // The fibre t = 0 from the complete witness set: its isolated points are endpoints.
  PointSet recovered(shape, cL);
  for (const PathEnd& e : track(*slice, yshape, qB, qA, randomGamma(rng.next()), W.points())) {
    if (e.status != PathStatus::kFinite) continue;
    recovered.add(CVec(e.x.head(n)));
  }
  out.fibre_roots = static_cast<int>(recovered.size());
  if (recovered.size() != moved.size())
    return fail("the witness set gives " + std::to_string(recovered.size()) +
                " fibre points, the start system " + std::to_string(moved.size()));
  // Every recovered point is a start root (none new, none missing: equal counts).
  for (const CVec& x : recovered.points())
    if (moved.add(x) != 0) return fail("a fibre point the start system does not hold");
  out.passed = true;
  return out;
}

}  // namespace

// Monodromy on the slice may stall short of the witness set (a point reached only around a few
// branch points): a new attempt (another line and slices) rather than more loops of the same.
TraceOutcome traceTest(const Family& f, const StartSystem& s, std::uint64_t seed) {
  TraceOutcome out;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    out = traceOnce(f, s, mixSeed(seed, attempt));
    out.attempts = attempt + 1;
    // A fibre point the start system lacks is an answer, not a stall.
    if (out.passed || out.fibre_roots > static_cast<int>(s.roots.size())) break;
  }
  return out;
}

}  // namespace relpos::complete::detail
