#include "krawczyk.hpp"

#include <Eigen/LU>
#include <cmath>

#include "rounded_interval.hpp"

namespace relpos::complete::detail {
namespace {

struct ComplexBox {
  FI re, im;
  ComplexBox() = default;
  explicit ComplexBox(double v) : re(v), im(0.0) {}
  ComplexBox(const FI& r, const FI& i) : re(r), im(i) {}
};
ComplexBox operator+(const ComplexBox& a, const ComplexBox& b) {
  return {a.re + b.re, a.im + b.im};
}
ComplexBox operator*(const ComplexBox& a, const ComplexBox& b) {
  return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
ComplexBox operator*(const FI& a, const ComplexBox& b) { return {a * b.re, a * b.im}; }
ComplexBox operator*(const ComplexBox& a, double b) { return {a.re * b, a.im * b}; }

bool finiteMatrix(const CMat& m) {
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (!std::isfinite(m.data()[i].real()) || !std::isfinite(m.data()[i].imag())) return false;
  return true;
}

// Whether the interval [lo, hi] + [−s, s] lies in (−r, r); upward rounding is active, so the
// sums are upper bounds of the exact ones.
bool inside(const FI& a, double s, double r) { return a.upper() + s < r && -a.lower() + s < r; }

}  // namespace

struct Certifier::Impl {
  const CompiledShape& shape;
  bool complex_coefficients = false;
  std::vector<FI> real_coeffs;         // a real member's enclosures
  std::vector<ComplexBox> box_coeffs;  // a complex member's (degenerate) coefficients
  std::vector<Complex> mid;            // midpoints, for the preconditioner
  EvalScratch scratch;
  std::vector<ComplexBox> cvalues, cx, cf, cJ;
  std::vector<FI> rvalues, rx, rf, rJ;

  Impl(const CompiledShape& s)
      : shape(s),
        scratch(s),
        cvalues(s.nodes()),
        cx(s.variables()),
        cf(s.variables()),
        cJ(s.variables() * s.variables()),
        rvalues(s.nodes()),
        rx(s.variables()),
        rf(s.variables()),
        rJ(s.variables() * s.variables()) {}

  template <class C>
  void evalComplex(const C* c, bool jacobian) {
    evaluateBox(shape, c, cx.data(), cvalues.data(), cf.data(), jacobian ? cJ.data() : nullptr);
  }
  void evalComplexMember(bool jacobian) {
    if (complex_coefficients)
      evalComplex(box_coeffs.data(), jacobian);
    else
      evalComplex(real_coeffs.data(), jacobian);
  }

  bool testComplex(const CVec& y, double r) {
    const int n = shape.variables();
    if (!(r > 0.0) || !std::isfinite(r)) return false;
    // Preconditioner in round-to-nearest, before the upward scope.
    CMat J(n, n);
    evaluate(shape, mid.data(), nullptr, y, scratch, nullptr, &J, nullptr);
    if (!finiteMatrix(J)) return false;
    const CMat Y = Eigen::PartialPivLU<CMat>(J).inverse();
    if (!finiteMatrix(Y)) return false;
    RoundUp up;
    for (int i = 0; i < n; ++i) cx[i] = ComplexBox(FI(y[i].real()), FI(y[i].imag()));
    evalComplexMember(false);  // f at the centre
    std::vector<ComplexBox>& fy = cf;
    ComplexBox a[kMaxVariables];
    for (int i = 0; i < n; ++i) {
      FI re(0.0), im(0.0);
      for (int k = 0; k < n; ++k) {
        const double A = -Y(i, k).real(), B = -Y(i, k).imag();
        re = re + (A * fy[k].re - B * fy[k].im);
        im = im + (A * fy[k].im + B * fy[k].re);
      }
      a[i] = {re, im};
    }
    const FI rad(-r, r);
    for (int i = 0; i < n; ++i) cx[i] = ComplexBox(FI(y[i].real()) + rad, FI(y[i].imag()) + rad);
    evalComplexMember(true);  // J over the box
    for (int i = 0; i < n; ++i) {
      // Row i of M = I − Y J(X); M_ij · ([−r, r] + i[−r, r]) ⊂ (|Re M_ij| + |Im M_ij|) r (1 + i)
      double s = 0.0;
      for (int j = 0; j < n; ++j) {
        FI re(i == j ? 1.0 : 0.0), im(0.0);
        for (int k = 0; k < n; ++k) {
          const double A = Y(i, k).real(), B = Y(i, k).imag();
          const ComplexBox& q = cJ[k * n + j];
          re = re - (A * q.re - B * q.im);
          im = im - (A * q.im + B * q.re);
        }
        s = s + (mag(re) + mag(im));
      }
      s = s * r;
      if (!std::isfinite(s) || !inside(a[i].re, s, r) || !inside(a[i].im, s, r)) return false;
    }
    return true;
  }

  bool testReal(const RVec& y, double r) {
    if (complex_coefficients) return false;  // a complex member has no real test
    const int n = shape.variables();
    if (!(r > 0.0) || !std::isfinite(r)) return false;
    const CVec yc = y.cast<Complex>();
    CMat Jc(n, n);
    evaluate(shape, mid.data(), nullptr, yc, scratch, nullptr, &Jc, nullptr);
    const RMat J = Jc.real();
    if (!J.allFinite()) return false;
    const RMat Y = Eigen::PartialPivLU<RMat>(J).inverse();
    if (!Y.allFinite()) return false;
    RoundUp up;
    for (int i = 0; i < n; ++i) rx[i] = FI(y[i]);
    evaluateBox(shape, real_coeffs.data(), rx.data(), rvalues.data(), rf.data(),
                static_cast<FI*>(nullptr));
    FI a[kMaxVariables];
    for (int i = 0; i < n; ++i) {
      FI acc(0.0);
      for (int k = 0; k < n; ++k) acc = acc + (-Y(i, k)) * rf[k];
      a[i] = acc;
    }
    const FI rad(-r, r);
    for (int i = 0; i < n; ++i) rx[i] = FI(y[i]) + rad;
    evaluateBox(shape, real_coeffs.data(), rx.data(), rvalues.data(), rf.data(), rJ.data());
    for (int i = 0; i < n; ++i) {
      double s = 0.0;
      for (int j = 0; j < n; ++j) {
        FI m(i == j ? 1.0 : 0.0);
        for (int k = 0; k < n; ++k) m = m - Y(i, k) * rJ[k * n + j];
        s = s + mag(m);
      }
      s = s * r;
      if (!std::isfinite(s) || !inside(a[i], s, r)) return false;
    }
    return true;
  }

  // The smallest passing radius from the ladder, or 0.
  double smallestRadius(const CVec& y) {
    const double scale = 1.0 + normInf(y);
    for (double r = 1e-12 * scale; r <= 1.0001e-3 * scale; r *= 10.0)
      if (testComplex(y, r)) return r;
    return 0.0;
  }
};

Certifier::Certifier(const CompiledShape& shape, const Interval* coefficients)
    : impl_(std::make_unique<Impl>(shape)) {
  const int t = shape.terms();
  impl_->real_coeffs.reserve(t);
  impl_->mid.reserve(t);
  for (int i = 0; i < t; ++i) {
    impl_->real_coeffs.emplace_back(coefficients[i].lower(), coefficients[i].upper());
    impl_->mid.emplace_back(0.5 * (coefficients[i].lower() + coefficients[i].upper()), 0.0);
  }
}

Certifier::Certifier(const CompiledShape& shape, const Complex* coefficients)
    : impl_(std::make_unique<Impl>(shape)) {
  impl_->complex_coefficients = true;
  const int t = shape.terms();
  for (int i = 0; i < t; ++i) {
    impl_->box_coeffs.emplace_back(FI(coefficients[i].real()), FI(coefficients[i].imag()));
    impl_->mid.push_back(coefficients[i]);
  }
}

Certifier::~Certifier() = default;

bool Certifier::testComplex(const CVec& y, double r) { return impl_->testComplex(y, r); }
bool Certifier::testReal(const RVec& y, double r) { return impl_->testReal(y, r); }

BoxCertificate Certifier::certify(const CVec& x) {
  BoxCertificate out;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i].real()) || !std::isfinite(x[i].imag())) return out;
  const double scale = 1.0 + normInf(x);
  if (!impl_->complex_coefficients && x.imag().cwiseAbs().maxCoeff() <= 1e-7 * scale) {
    // A real candidate: the complex box around its real part (one root there), and the real
    // box (a real root there): the one root is real.
    const RVec yr = x.real();
    const CVec yc = yr.cast<Complex>();
    const double r = impl_->smallestRadius(yc);
    for (const double rr : {r, 10.0 * r}) {
      if (r > 0.0 && impl_->testReal(yr, rr) && (rr == r || impl_->testComplex(yc, rr))) {
        out.ok = true;
        out.x = yc;
        out.radius = rr;
        out.real = true;
        return out;
      }
    }
  }
  const double r = impl_->smallestRadius(x);
  if (r > 0.0) {
    out.ok = true;
    out.x = x;
    out.radius = r;
  }
  return out;
}

bool boxesOverlap(const CVec& a, double ra, const CVec& b, double rb) {
  if (a.size() != b.size()) return false;
  // A margin of a few ulps against the rounding of the differences and the sum.
  const double reach = (ra + rb) * (1.0 + 1e-12);
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double dre = std::abs(a[i].real() - b[i].real());
    const double dim = std::abs(a[i].imag() - b[i].imag());
    const double tiny = 4e-16 * (std::abs(a[i].real()) + std::abs(b[i].real()) +
                                 std::abs(a[i].imag()) + std::abs(b[i].imag()));
    if (dre > reach + tiny || dim > reach + tiny) return false;
  }
  return true;
}

}  // namespace relpos::complete::detail
