#pragma once
// A family of square polynomial systems F(x; p) = 0 sharing one shape, whose coefficients are
// polynomials in complex parameters p (docs/spec.md §8, issue 15). The numeric stage solves a
// real member (the problem, encoded) by coefficient-parameter homotopy from a generic complex
// member whose roots were computed once per signature (start_system.hpp), then certifies every
// endpoint (certify.hpp). The engine (homotopy, certification, start systems) sees only this
// interface; the encodings of relpos's constraints (encoding.hpp) implement it.
#include <array>
#include <complex>
#include <cstdint>
#include <string>
#include <vector>

#include <boost/numeric/interval.hpp>

namespace relpos::complete {

using Complex = std::complex<double>;
// Rigorous real interval (Boost.Interval's default policies for double: every operation rounds
// outward, saving and restoring the rounding mode itself).
using Interval = boost::numeric::interval<double>;

inline constexpr int kMaxVariables = 16;
inline constexpr int kMaxMonomialDegree = 4;

// A monomial x_vars[0] · … · x_vars[degree-1] (variables sorted, repeated by power); degree 0 is 1.
struct Monomial {
  std::uint8_t degree = 0;
  std::array<std::uint8_t, kMaxMonomialDegree> vars{};
  friend bool operator==(const Monomial& a, const Monomial& b) {
    return a.degree == b.degree && a.vars == b.vars;
  }
};

// The shape of a square system in `variables` unknowns: equation k is the sum over the terms t
// with terms[t].equation == k of coefficient[t] · monomials[terms[t].monomial]. Coefficient
// vectors are indexed by term.
struct SystemShape {
  int variables = 0;  // = number of equations
  std::vector<Monomial> monomials;
  struct Term {
    std::uint16_t equation = 0;
    std::uint16_t monomial = 0;
  };
  std::vector<Term> terms;
};

class Family {
 public:
  virtual ~Family() = default;
  // Equal signatures mean the same shape, parameter count and coefficient map: the start system
  // cache is keyed by it.
  virtual const std::string& signature() const = 0;
  virtual const SystemShape& shape() const = 0;
  virtual int parameterCount() const = 0;
  // The largest total degree of a coefficient as a polynomial in the parameters (the homotopy
  // interpolates the coefficients along a segment of parameter space from degree + 1 nodes).
  virtual int coefficientDegree() const = 0;
  // coeffs[t] for every term t of shape(), at complex parameters.
  virtual void coefficients(const Complex* params, Complex* coeffs) const = 0;
  // An enclosure of coeffs[t] for parameters within the given intervals (for certification of a
  // real member: degenerate intervals around its exact double parameters).
  virtual void coefficients(const Interval* params, Interval* coeffs) const = 0;
  // A random complex member with one root known (the seed of monodromy): fills params
  // (parameterCount()) and root (shape().variables), deterministically from `seed`.
  virtual void seedMember(std::uint64_t seed, Complex* params, Complex* root) const = 0;
};

}  // namespace relpos::complete
