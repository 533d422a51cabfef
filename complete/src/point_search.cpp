#include "point_search.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "chart.hpp"

namespace relpos::complete::detail {
namespace {

// How far into a range the descent aims: its inner half (a one-sided range: this far past its
// bound, in the normalised units); then, when the inner parts of the ranges do not meet on the
// equations' set, closer to the edges.
constexpr double kShrinks[] = {0.25, 0.05, 0.005};
// A one-sided range's margin per unit of shrink: 0.05 past its bound at the first aim.
constexpr double kOneSidedPerShrink = 0.2;

// The descent stops at a stationary point of a positive cost (|Jᵀr| this small against |r| |J|)
// or after this many steps in a row that lower the cost by less than this fraction: the
// linear convergence towards a positive minimum, where no pose is.
constexpr double kStationary = 1e-9;
constexpr double kProgress = 1e-3;
constexpr int kSlowSteps = 8;

// The least-squares cost Σ r² and, with the Jacobian, its normal equations JᵀJ and Jᵀr,
// accumulated row by row (no matrix of all the rows: a handful of rows, products of fixed size).
struct Residuals {
  double cost = 0.0;
  Matrix6d JtJ = Matrix6d::Zero();
  Vector6d Jtr = Vector6d::Zero();
};

double innerLo(const Condition& c, double shrink) {
  if (!std::isfinite(c.lo)) return c.lo;
  return std::isfinite(c.hi) ? c.lo + shrink * (c.hi - c.lo) : c.lo + kOneSidedPerShrink * shrink;
}
double innerHi(const Condition& c, double shrink) {
  if (!std::isfinite(c.hi)) return c.hi;
  return std::isfinite(c.lo) ? c.hi - shrink * (c.hi - c.lo) : c.hi - kOneSidedPerShrink * shrink;
}

double valueOf(double g) { return g; }
double valueOf(const Dual<double>& g) { return g.v; }

// The residuals at coordinates y about (R0, t0), the conditions already in that base frame:
// T = Dual<double> with the Jacobian (always at the base, y = 0), double without (a trial
// step's cost: a third of the descent's evaluations, at a fraction of the derivatives' price).
template <typename T>
void residuals(const std::vector<Condition>& eq, const std::vector<Condition>& in,
               const Vector6d& y, double shrink, Residuals* out) {
  constexpr bool kJacobian = !std::is_same_v<T, double>;
  const LocalPose<T> X = [&] {
    if constexpr (kJacobian) {
      return LocalPose<T>(typename LocalPose<T>::AtBase{});
    } else {
      std::array<double, 6> yv;
      for (int i = 0; i < 6; ++i) yv[i] = y[i];
      return LocalPose<T>(yv);
    }
  }();
  *out = Residuals{};
  auto put = [&](const T& g, double excess) {
    out->cost += excess * excess;
    if constexpr (kJacobian) {
      if (excess == 0.0) return;
      const Vector6d row = Eigen::Map<const Vector6d>(g.g.data());
      out->JtJ.noalias() += row * row.transpose();
      out->Jtr += excess * row;
    }
  };
  for (const Condition& c : eq) {
    const T g = evaluate(c, X);
    put(g, valueOf(g) - c.lo);
  }
  for (const Condition& c : in) {
    const T g = evaluate(c, X);
    const double v = valueOf(g), lo = innerLo(c, shrink), hi = innerHi(c, shrink);
    put(g, v < lo ? v - lo : (v > hi ? v - hi : 0.0));
  }
}

bool holds(const ConditionSystem& s, const Matrix3d& R, const Vector3d& t,
           const EquationSlack& slack) {
  std::vector<Condition> eq, in;
  inBaseFrame(s.equations, R, t, &eq);
  inBaseFrame(s.inequalities, R, t, &in);
  const std::array<double, 6> y{};
  const LocalPose<double> X(y);
  for (const Condition& c : eq) {
    const double off = std::abs(evaluate(c, X) - c.lo);
    if (off <= 1e-12) continue;
    const double allowed = toleranceInUnits(c, slack.length, slack.angle);
    if (!(off <= allowed)) return false;
  }
  for (const Condition& c : in) {
    const double g = evaluate(c, X);
    if (!(c.lo < g && g < c.hi)) return false;
  }
  return true;
}

// One descent towards the ranges shrunk by `shrink`.
void descend(const ConditionSystem& s, double shrink, Matrix3d* R, Vector3d* t) {
  double lambda = 1e-3;
  int slow = 0;  // successful steps that barely lowered the cost
  std::vector<Condition> eq, in;
  Residuals cur, trial;
  auto rebase = [&] {
    inBaseFrame(s.equations, *R, *t, &eq);
    inBaseFrame(s.inequalities, *R, *t, &in);
    residuals<Dual<double>>(eq, in, Vector6d::Zero(), shrink, &cur);
  };
  rebase();
  for (int it = 0; it < 200 && cur.cost > 1e-30; ++it) {
    const Matrix6d& JtJ = cur.JtJ;
    const Vector6d& g = cur.Jtr;
    Matrix6d A = JtJ;
    A.diagonal().array() += lambda * (1.0 + JtJ.diagonal().array());
    const Vector6d step = -A.ldlt().solve(g);
    if (!step.allFinite()) return;
    // a stationary point of a positive cost (no pose near, or a local minimum): stop there
    if (g.norm() <= kStationary * std::sqrt(cur.cost) * (1.0 + std::sqrt(JtJ.diagonal().sum())))
      return;
    residuals<double>(eq, in, step, shrink, &trial);
    if (trial.cost < cur.cost) {
      slow = trial.cost > (1.0 - kProgress) * cur.cost ? slow + 1 : 0;
      if (slow >= kSlowSteps) return;
      Matrix3d R2;
      Vector3d t2;
      poseAt(*R, *t, step, &R2, &t2);
      *R = Eigen::Quaterniond(R2).normalized().toRotationMatrix(), *t = t2;
      rebase();
      lambda = std::max(lambda / 3.0, 1e-12);
    } else {
      lambda *= 4.0;
      if (lambda > 1e12) break;
    }
    if (step.norm() < 1e-15) break;
  }
}

}  // namespace

void polishPose(const std::vector<Condition>& equations, Matrix3d* R, Vector3d* t) {
  const auto m = static_cast<Eigen::Index>(equations.size());
  if (m == 0 || m > 6) return;
  std::vector<Condition> eq;
  EquationVector e;
  EquationJacobian J;
  inBaseFrame(equations, *R, *t, &eq);
  equationsAt(eq, Vector6d::Zero(), &e, &J);
  double residual = e.lpNorm<Eigen::Infinity>(), moved = 0.0;
  for (int it = 0; it < 3 && residual > 1e-16; ++it) {
    const EquationMatrix JJt = J * J.transpose();
    const Vector6d step = -J.transpose() * JJt.ldlt().solve(e);
    if (!step.allFinite() || moved + step.norm() > 1e-6) return;
    Matrix3d R2;
    Vector3d t2;
    poseAt(*R, *t, step, &R2, &t2);
    R2 = Eigen::Quaterniond(R2).normalized().toRotationMatrix();
    inBaseFrame(equations, R2, t2, &eq);
    EquationVector e2;
    EquationJacobian J2;
    equationsAt(eq, Vector6d::Zero(), &e2, &J2);
    const double r2 = e2.lpNorm<Eigen::Infinity>();
    if (!(r2 < residual)) return;
    *R = R2, *t = t2, e = e2, J = J2, residual = r2, moved += step.norm();
  }
}

bool findPoint(const ConditionSystem& s, Matrix3d* R, Vector3d* t, const EquationSlack& slack) {
  for (double shrink : kShrinks) {
    descend(s, shrink, R, t);
    if (!R->allFinite() || !t->allFinite()) return false;
    // the descent's last steps creep (it stops after eight that barely lower the cost): Newton's
    // method finishes a regular point's last digits
    polishPose(s.equations, R, t);
    if (holds(s, *R, *t, slack)) return true;
    if (s.inequalities.empty()) return false;  // the shrink changes nothing
  }
  return false;
}

}  // namespace relpos::complete::detail
