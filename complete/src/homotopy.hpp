#pragma once
// Path tracking for coefficient-parameter homotopies (Morgan & Sommese 1989). The coefficients
// along a segment p(τ) = p0 + τ (p1 − p0) of parameter space are polynomials in τ of the family's
// coefficient degree, recovered exactly (up to rounding) by interpolation; τ runs along the arc
// τ(s) = γ s / (1 + (γ − 1) s), s ∈ [0, 1] (the γ trick: for all but finitely many γ on the unit
// circle the arc misses every point where roots meet). RK4 predictor, Newton corrector, step
// control on the corrector's first step; diverging paths are classified as going to infinity.
#include <cstdint>
#include <vector>

#include "polynomial_eval.hpp"
#include "small_lu.hpp"

namespace relpos::complete::detail {

// c_t(τ) = Σ_j a[t (degree + 1) + j] τ^j for every term t.
struct CoefficientPolynomials {
  int terms = 0;
  int degree = 0;
  std::vector<Complex> a;
  // c (and dc = dc/dτ if not null) at τ.
  void evaluate(Complex tau, Complex* c, Complex* dc) const;
  // The same at a real argument (the tracker's, along its arc: alongArc below), both computed.
  void evaluate(double s, Complex* c, Complex* dc) const;
};

// The coefficients of f along p0 → p1 from f.coefficients at degree + 1 equally spaced nodes.
CoefficientPolynomials interpolateSegment(const Family& f, const Complex* p0, const Complex* p1);

// τ(s) = γ s / (1 + (γ − 1) s): τ(0) = 0, τ(1) = 1; γ = 1 is the straight segment.
struct Arc {
  Complex gamma{1.0, 0.0};
  Complex tau(double s) const;
  Complex dtau(double s) const;  // dτ/ds
};

// The coefficients along the arc as polynomials in s of the same degree d: D(s)^d c(τ(s)) with
// D(s) = 1 + (γ − 1) s, which clears τ's denominator. The factor, never zero on [0, 1] (|D| ≥
// cos(θ/2) for γ = e^{iθ}), leaves every root and every Newton step unchanged, and the tracker's
// coefficients cost a real Horner scheme instead of a complex one and a chain rule.
CoefficientPolynomials alongArc(const CoefficientPolynomials& p, Complex gamma);

// γ = e^{iθ} with |θ| in [0.25, 2.25] from a seed (θ near ±π bends the arc far from [0, 1]).
Complex randomGamma(std::uint64_t seed);

enum class PathStatus { kFinite, kAtInfinity, kFailed };

struct PathEnd {
  CVec x;
  PathStatus status = PathStatus::kFailed;
  int steps = 0;     // predictor-corrector steps tried
  int rejected = 0;  // of which rejected (the step halved)
};

struct TrackerOptions {
  double initial_step = 0.05;
  double max_step = 0.25;
  double min_step = 1e-13;
  int max_steps = 4000;
  // The corrector's first step relative to 1 + |x|: the step size aims at `target_error`, and a
  // step is rejected above `max_error` (a small basin guards against jumping to another path).
  // Measured on the 6-6 Stewart family (steps a path): 96 at 1e-6, 64 at 1e-5, 41 at 1e-4, 29
  // at 1e-3, each finding every root on 30 random real platforms in one attempt. Soundness does
  // not depend on it: a jump to another path shows as two overlapping boxes and a retrack.
  double target_error = 1e-3;
  double max_error = 1e-2;
  // Above this first correction a second Newton step must confirm the contraction.
  double confirm_error = 1e-3;
  // |x|∞ beyond divergence · (1 + |start|∞): the path goes to infinity.
  double divergence = 1e7;
};

class Tracker {
 public:
  // end_coefficients (terms, may be null): the exact coefficients at s = 1, for the final
  // Newton polish (the interpolated ones carry rounding).
  Tracker(const CompiledShape& shape, const CoefficientPolynomials& coefficients, Arc arc,
          const Complex* end_coefficients, const TrackerOptions& options = TrackerOptions());
  PathEnd track(const CVec& start);

 private:
  void coefficientsAt(double s);
  bool velocity(const CVec& x, double s, CVec& v);
  // y: the RK4 prediction from x (velocity v) at s to s1 = s + h.
  bool rungeKutta(const CVec& x, const CVec& v, double s, double h, double s1, CVec& y);
  // One Newton step of H(·, s) at x: x -= step; returns |step|∞, or a negative number if the
  // Jacobian is singular or the result not finite. v (if not null): the velocity at x before
  // the step, from the same Jacobian.
  double newton(CVec& x, double s, CVec* v);
  // A simplified Newton step at x with the last factored Jacobian (same s): f only.
  double chord(CVec& x);

  const CompiledShape& shape_;
  CoefficientPolynomials poly_;  // in s (alongArc)
  const Complex* end_;
  TrackerOptions options_;
  EvalScratch scratch_;
  std::vector<Complex> c_, dc_;
  double s_cached_ = -1.0;
  CVec f_, fs_;
  CMat J_;
  SmallLU lu_;
  CVec d_;
  CVec k2_, k3_, k4_, z_;  // RK4's stage velocities and stage point
};

// Newton on F with coefficients c until the step is below 1e-15 (1 + |x|) or `iterations`:
// returns the last step's size relative to 1 + |x|∞ (negative on failure).
double polish(const CompiledShape& shape, const Complex* c, CVec& x, EvalScratch& scratch,
              int iterations);

}  // namespace relpos::complete::detail
