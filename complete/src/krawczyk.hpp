#pragma once
// Krawczyk's test (Krawczyk 1969, Rump's form): for a box X = y ± r, a point preconditioner
// Y ≈ J(y)⁻¹ and the interval Jacobian J(X), if K = −Y f(y) + (I − Y J(X)) [−r, r] lies strictly
// inside [−r, r] in every coordinate, then X holds exactly one root and J is nonsingular on X.
// Complex roots are tested on complex boxes (every real and imaginary part ± r; the complex form
// of the realified test); a root with tiny imaginary parts is tested also on the real box around
// its real part with real arithmetic, which proves it real. All interval work runs under one
// upward-rounding scope (Boost.Interval's rounded_arith_opp): outward rounding throughout. This
// unit is compiled with -frounding-math and never with -ffast-math.
#include <memory>

#include "polynomial_eval.hpp"

namespace relpos::complete::detail {

struct BoxCertificate {
  bool ok = false;
  CVec x;               // the box centre
  double radius = 0.0;  // x ± radius on every real and imaginary part holds exactly one root
  bool real = false;    // the real box around Re x passed too: the root is real
};

// Certifies roots of one member: a real one (interval coefficients, e.g. from
// Family::coefficients(Interval*) at the target's exact parameters) or a complex one given by
// its double coefficients (the start systems: the member is its coefficients as stored).
class Certifier {
 public:
  Certifier(const CompiledShape& shape, const Interval* coefficients);
  Certifier(const CompiledShape& shape, const Complex* coefficients);
  ~Certifier();
  Certifier(const Certifier&) = delete;
  Certifier& operator=(const Certifier&) = delete;

  // The smallest radius 10^k · 1e-12 (1 + |x|∞), up to 1e-3 (1 + |x|∞), that passes.
  BoxCertificate certify(const CVec& x);
  // One test at one radius (tests).
  bool testComplex(const CVec& y, double r);
  bool testReal(const RVec& y, double r);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Whether the boxes a ± ra and b ± rb (every real and imaginary part) share a point; rounding
// in the comparison counts against disjointness.
bool boxesOverlap(const CVec& a, double ra, const CVec& b, double rb);

}  // namespace relpos::complete::detail
