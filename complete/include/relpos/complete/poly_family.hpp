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

  // Which parameters the equations read: coordinates (a slot of `width`) and each equation's
  // value parameter (-1: none). checked() throws std::invalid_argument unless every index is
  // below parameter_count and each value parameter belongs to one equation only and is no
  // coordinate (what solveValueParameters needs); it returns the value parameters by equation.
  class ParameterUse {
   public:
    void coordinates(int offset, int width);
    void value(int v) { values_.push_back(v); }
    std::vector<int> checked(int parameter_count) const;

   private:
    std::vector<std::pair<int, int>> slots_;
    std::vector<int> values_;
  };

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

// PolyFamily's three scalar passes from one member template of Derived,
// `template <typename S> Poly<S> equation(std::size_t k, const S* params) const`, over
// `equationCount()` equations.
template <typename Derived>
class PolyFamilyOf : public PolyFamily {
 protected:
  void equations(const Structure* p, std::vector<Poly<Structure>>& out) const override {
    write(p, out);
  }
  void equations(const Complex* p, std::vector<Poly<Complex>>& out) const override {
    write(p, out);
  }
  void equations(const Interval* p, std::vector<Poly<Interval>>& out) const override {
    write(p, out);
  }

 private:
  template <typename S>
  void write(const S* p, std::vector<Poly<S>>& out) const {
    const Derived& self = static_cast<const Derived&>(*this);
    out.clear();
    for (std::size_t k = 0; k < self.equationCount(); ++k) out.push_back(self.equation(k, p));
  }
};

}  // namespace relpos::complete
