#pragma once
// Families for testing the numeric engine without the constraint encodings: two generic conics
// in C² (4 roots; two circles meet twice at infinity), and the 6-6 Stewart–Gough point-distance
// family in Study parameters exactly as the prototype's make_phc.py builds it (40 roots).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "relpos/complete/family.hpp"

namespace relpos::complete::testing {

// x = (x, y); params: conic k (k = 0, 1) is
// p[6k] x² + p[6k+1] x y + p[6k+2] y² + p[6k+3] x + p[6k+4] y + p[6k+5].
class ConicFamily : public Family {
 public:
  ConicFamily();
  const std::string& signature() const override { return signature_; }
  const SystemShape& shape() const override { return shape_; }
  int parameterCount() const override { return 12; }
  int coefficientDegree() const override { return 1; }
  void coefficients(const Complex* params, Complex* coeffs) const override;
  void coefficients(const Interval* params, Interval* coeffs) const override;
  void seedMember(std::uint64_t seed, Complex* params, Complex* root) const override;

 private:
  std::string signature_ = "test:two-conics";
  SystemShape shape_;
};

// The conic tests' family (made on first use: its terms are another file's static data), and a
// point (x, y) of C² as they write roots.
inline const ConicFamily& twoConics() {
  static const ConicFamily family;
  return family;
}
inline Eigen::VectorXcd conicPoint(Complex x, Complex y) {
  Eigen::VectorXcd v(2);
  v << x, y;
  return v;
}

// n equations in n unknowns, each with every monomial of degree ≤ d, coefficients = params
// (equation-major, monomials in shape() order): generic root count d^n (Bézout).
class DenseFamily : public Family {
 public:
  DenseFamily(int n, int d);
  const std::string& signature() const override { return signature_; }
  const SystemShape& shape() const override { return shape_; }
  int parameterCount() const override { return static_cast<int>(shape_.terms.size()); }
  int coefficientDegree() const override { return 1; }
  void coefficients(const Complex* params, Complex* coeffs) const override;
  void coefficients(const Interval* params, Interval* coeffs) const override;
  // Random coefficients; each equation's constant term makes `root` a root.
  void seedMember(std::uint64_t seed, Complex* params, Complex* root) const override;
  // The monomial of term t at x (to build members through known points).
  Complex monomialValue(int term, const Complex* x) const;

 private:
  std::string signature_;
  SystemShape shape_;
};

// x = (e0..e3, g0..g3). Equations: Study quadric e·g = 0; leg 1 |e b1 − a1 e + 2g|² − d1² |e|²;
// legs 2..6 minus leg 1; chart c·e − 1. params: c (4), then per leg a (3), b (3), d² (1).
class StewartFamily : public Family {
 public:
  // A signature of its own gives a start system of its own (benchmarks of startSystem).
  explicit StewartFamily(std::string signature = "test:stewart-6-6-study");
  const std::string& signature() const override { return signature_; }
  const SystemShape& shape() const override { return shape_; }
  int parameterCount() const override { return 46; }
  int coefficientDegree() const override { return 2; }
  void coefficients(const Complex* params, Complex* coeffs) const override;
  void coefficients(const Interval* params, Interval* coeffs) const override;
  void seedMember(std::uint64_t seed, Complex* params, Complex* root) const override;

 private:
  std::string signature_;
  SystemShape shape_;
};

// A real Stewart member with the known root x = (e, g): d_i² = |e b_i − a_i e + 2g|² / |e|²,
// c = c_raw / (c_raw · e). Exact in double when the inputs are dyadic with |e|² and c_raw · e
// powers of two (then x is an exact root of the returned member).
struct StewartPose {
  std::array<double, 4> e, g;
};
std::vector<double> stewartMemberAround(const StewartPose& pose,
                                        const std::array<std::array<double, 3>, 6>& a,
                                        const std::array<std::array<double, 3>, 6>& b,
                                        const std::array<double, 4>& c_raw);

// A random real platform (anchors a in [−2, 2]³, b in [−1, 1]³) around a random real pose, which
// it returns in `pose`; the same for the same seed.
std::vector<double> randomStewartMember(std::uint64_t seed, StewartPose& pose);

}  // namespace relpos::complete::testing
