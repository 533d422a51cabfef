#pragma once
// What the pose and line encodings share (encoding.hpp): a Family whose equations are written
// once as polynomials over a scalar type (poly.hpp) — the shape and coefficient degree come from
// the Structure pass, the coefficients from the Complex and Interval ones, scattered into the
// shape's term order — and the seed member's value parameters, each solved from its own
// (affine) equation so that a random root satisfies the member.
#include <random>
#include <string>
#include <vector>

#include "relpos/complete/family.hpp"
#include "relpos/complete/poly.hpp"

namespace relpos::complete {

class PolyFamily : public Family {
 public:
  const std::string& signature() const override { return signature_; }
  const SystemShape& shape() const override { return shape_; }
  int parameterCount() const override { return parameter_count_; }
  int coefficientDegree() const override { return coefficient_degree_; }
  void coefficients(const Complex* params, Complex* coeffs) const override;
  void coefficients(const Interval* params, Interval* coeffs) const override;

  // The equations as polynomials at complex parameters (for tests and seedMember).
  std::vector<Poly<Complex>> equationsAt(const Complex* params) const;

 protected:
  // variables: the unknowns; signature: what the derived class says fixes its equations.
  void build(int variables, int parameter_count, std::string signature);
  // Completes a seed member: params holds random values everywhere but in the value parameters
  // (value_param[k] >= 0: equation k is affine in that parameter, used by no other equation),
  // root a point; each value parameter is set so that its equation vanishes at the root.
  void solveValueParameters(const std::vector<int>& value_param, Complex* params,
                            const Complex* root) const;

  // A complex number with real and imaginary parts uniform in [-1, 1], from the raw bits of the
  // generator (the standard distributions differ between libraries: seeds must give the same
  // member everywhere).
  static Complex randomComplex(std::mt19937_64& rng);

  virtual void equations(const Structure* params, std::vector<Poly<Structure>>& out) const = 0;
  virtual void equations(const Complex* params, std::vector<Poly<Complex>>& out) const = 0;
  virtual void equations(const Interval* params, std::vector<Poly<Interval>>& out) const = 0;

 private:
  template <typename S>
  void scatter(const std::vector<Poly<S>>& eqs, S* coeffs) const;

  std::string signature_;
  SystemShape shape_;
  int parameter_count_ = 0;
  int coefficient_degree_ = 0;
  // Per equation, its terms' keys (sorted) and their indices in shape_.terms.
  std::vector<std::vector<MonomialKey>> keys_;
  std::vector<int> first_term_;
};

}  // namespace relpos::complete
