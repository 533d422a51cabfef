#pragma once
// The interval type of the proofs (krawczyk.cpp, exclusion.cpp): Boost.Interval with every
// operation assuming the FPU rounds upward (lower bounds by negation), so that one RoundUp scope
// around a whole test sets the mode once instead of at every operation. Units that include this
// are compiled with -frounding-math and never with -ffast-math.
#include <algorithm>
#include <utility>
#include <boost/numeric/interval.hpp>

namespace relpos::complete::detail {

using FI = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<
                boost::numeric::interval_lib::save_state_nothing<
                    boost::numeric::interval_lib::rounded_arith_opp<double>>,
                boost::numeric::interval_lib::checking_base<double>>>;
// Upward rounding for its scope; the caller's mode restored after.
using RoundUp = boost::numeric::interval_lib::save_state<
    boost::numeric::interval_lib::rounded_arith_opp<double>>;

// A point of the interval (its midpoint up to rounding) without a change of rounding mode, as
// Boost's median makes twice: halves are exact and their upward-rounded sum stays ≤ upper().
inline double midpoint(const FI& a) { return 0.5 * a.lower() + 0.5 * a.upper(); }

// The two halves of a box's coordinate at its midpoint (the bisection of the interval proofs).
inline std::pair<FI, FI> halves(const FI& a) {
  const double m = midpoint(a);
  return {FI(a.lower(), m), FI(m, a.upper())};
}

// max |x| over the interval.
inline double mag(const FI& a) { return std::max(-a.lower(), a.upper()); }

}  // namespace relpos::complete::detail
