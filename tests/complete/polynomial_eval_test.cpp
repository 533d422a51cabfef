// The shared monomial evaluation: values against a direct sum of terms, the Jacobian against
// central differences, and interval boxes enclosing the point values.
#include "polynomial_eval.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_families.hpp"

namespace relpos::complete {
namespace {

using detail::CompiledShape;
using detail::CVec;

// F(x) straight from the SystemShape, one term at a time.
CVec direct(const SystemShape& s, const std::vector<Complex>& c, const CVec& x) {
  CVec f = CVec::Zero(s.variables);
  for (std::size_t t = 0; t < s.terms.size(); ++t) {
    const Monomial& m = s.monomials[s.terms[t].monomial];
    Complex v = c[t];
    for (int j = 0; j < m.degree; ++j) v *= x[m.vars[j]];
    f[s.terms[t].equation] += v;
  }
  return f;
}

TEST(PolynomialEval, ValuesJacobianAndParameterDerivativeMatchDirectSums) {
  const testing::StewartFamily stewart;
  const testing::DenseFamily dense(3, 4);
  for (const Family* f :
       {static_cast<const Family*>(&stewart), static_cast<const Family*>(&dense)}) {
    const SystemShape& s = f->shape();
    const CompiledShape shape(s);
    std::mt19937_64 rng(4);
    std::normal_distribution<double> g;
    std::vector<Complex> c(s.terms.size()), dc(s.terms.size());
    for (auto& v : c) v = {g(rng), g(rng)};
    for (auto& v : dc) v = {g(rng), g(rng)};
    CVec x(s.variables);
    for (auto& v : x) v = {g(rng), g(rng)};
    detail::EvalScratch scratch(shape);
    CVec fx(s.variables), fs(s.variables);
    detail::CMat J(s.variables, s.variables);
    detail::evaluate(shape, c.data(), dc.data(), x, scratch, &fx, &J, &fs);
    EXPECT_LT((fx - direct(s, c, x)).norm(), 1e-12 * (1 + fx.norm()));
    EXPECT_LT((fs - direct(s, dc, x)).norm(), 1e-12 * (1 + fs.norm()));
    const double h = 1e-6;
    for (int v = 0; v < s.variables; ++v) {
      CVec xp = x, xm = x;
      xp[v] += h;
      xm[v] -= h;
      const CVec d = (direct(s, c, xp) - direct(s, c, xm)) / (2 * h);
      EXPECT_LT((J.col(v) - d).norm(), 1e-6 * (1 + d.norm())) << "column " << v;
    }
  }
}

// Real intervals: the box around x encloses F at x and at the box's corners.
TEST(PolynomialEval, RealBoxEnclosesPointValues) {
  const testing::DenseFamily dense(2, 4);
  const CompiledShape shape(dense.shape());
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Interval> c(shape.terms());
  std::vector<Complex> cc(shape.terms());
  for (int t = 0; t < shape.terms(); ++t) {
    const double v = u(rng);
    c[t] = v;
    cc[t] = v;
  }
  const double x0 = u(rng), x1 = u(rng), r = 1e-3;
  const Interval box[2] = {Interval(x0 - r, x0 + r), Interval(x1 - r, x1 + r)};
  std::vector<Interval> values(shape.nodes());
  Interval f[2], J[4];
  detail::evaluateBox(shape, c.data(), box, values.data(), f, J);
  detail::EvalScratch scratch(shape);
  for (const double a : {x0 - r, x0, x0 + r})
    for (const double b : {x1 - r, x1, x1 + r}) {
      CVec x(2), fx(2);
      x << a, b;
      detail::CMat Jx(2, 2);
      detail::evaluate(shape, cc.data(), nullptr, x, scratch, &fx, &Jx, nullptr);
      for (int e = 0; e < 2; ++e) {
        EXPECT_TRUE(boost::numeric::in(fx[e].real(), f[e]));
        for (int v = 0; v < 2; ++v) EXPECT_TRUE(boost::numeric::in(Jx(e, v).real(), J[e * 2 + v]));
      }
    }
}

}  // namespace
}  // namespace relpos::complete
