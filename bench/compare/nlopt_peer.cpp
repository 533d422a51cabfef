#include <nlopt.h>

#include <cmath>
#include <vector>

#include "evaluator.hpp"
#include "peers.hpp"

namespace relpos::compare {
namespace {

struct Data {
  const Problem* p;
  int constraint = -1;  // for an inequality: which constraint
};

Isometry3d poseOf(const Problem& p, const double* x) {
  const Vector3d w(x[0], x[1], x[2]);
  Isometry3d X = p.mobile.pose;
  if (w.norm() > 0) X.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()) * X.linear();
  X.translation() += Vector3d(x[3], x[4], x[5]);
  return X;
}

double objectiveAt(const Problem& p, const double* x) {
  const Isometry3d X = poseOf(p, x);
  double f = 0;
  for (const auto& c : p.constraints)
    if (!isRange(c)) {
      const double v = test::violation(c, p.fixed.pose, X);
      f += v * v;
    }
  return f;
}

template <typename F>
void centralDifferences(unsigned n, const double* x, double* grad, F f) {
  std::vector<double> y(x, x + n);
  for (unsigned i = 0; i < n; ++i) {
    const double h = 1e-7;
    y[i] = x[i] + h;
    const double up = f(y.data());
    y[i] = x[i] - h;
    const double down = f(y.data());
    y[i] = x[i];
    grad[i] = (up - down) / (2 * h);
  }
}

double objective(unsigned n, const double* x, double* grad, void* data) {
  const Problem& p = *static_cast<Data*>(data)->p;
  if (grad) centralDifferences(n, x, grad, [&](const double* y) { return objectiveAt(p, y); });
  return objectiveAt(p, x);
}

double inequality(unsigned n, const double* x, double* grad, void* data) {
  const Data& d = *static_cast<Data*>(data);
  const InputConstraint& c = d.p->constraints[static_cast<std::size_t>(d.constraint)];
  auto f = [&](const double* y) { return test::violation(c, d.p->fixed.pose, poseOf(*d.p, y)); };
  if (grad) centralDifferences(n, x, grad, f);
  return f(x);
}

}  // namespace

PeerResult solveWithNlopt(const Problem& p) {
  PeerResult r;
  nlopt_opt opt = nlopt_create(NLOPT_LD_SLSQP, 6);
  Data all{&p};
  std::vector<Data> ranges;
  ranges.reserve(p.constraints.size());
  nlopt_set_min_objective(opt, objective, &all);
  for (std::size_t i = 0; i < p.constraints.size(); ++i)
    if (isRange(p.constraints[i])) {
      ranges.push_back({&p, static_cast<int>(i)});
      nlopt_add_inequality_constraint(opt, inequality, &ranges.back(), 1e-9);
    }
  nlopt_set_xtol_rel(opt, 1e-12);
  nlopt_set_ftol_abs(opt, 1e-20);
  nlopt_set_maxeval(opt, 500);
  double x[6] = {0, 0, 0, 0, 0, 0}, f = 0;
  const nlopt_result res = nlopt_optimize(opt, x, &f);
  nlopt_destroy(opt);
  r.converged = res > 0;
  r.pose = poseOf(p, x);
  return r;
}

Problem midRangeVariant(const Problem& p) {
  Problem q = p;
  for (auto& c : q.constraints)
    if (isRange(c)) {
      const bool lo = std::isfinite(c.min), hi = std::isfinite(c.max);
      c.value = lo && hi ? 0.5 * (c.min + c.max) : (lo ? c.min : c.max);
      c.has_value = true;
    }
  return q;
}

}  // namespace relpos::compare
