#pragma once
// Polynomial systems of the benchmark problems for PHCpack, written the way the design's
// prototype writes them (/work/shared/design/homotopy-prototype/make_phc.py):
// - six point-point distances (Stewart-Gough 6-6, octahedral 3-3): Study parameters e (q0..q3)
//   and g (h0..h3), world point = R b + t with R = e·e*/|e|² and t = 2 g e*/|e|²; the Study
//   quadric e·g = 0, leg 1 |e b − a e + 2 g|² − d²|e|² = 0, legs 2..6 minus leg 1 (no g·g term),
//   and a random real chart c·e = 1 (the chart e0 = 1 loses every pose turned by 180°);
// - four point-line distances (the mobile object one line): Plücker coordinates, direction d and
//   moment m, d·m = 0, |c_i × d − m|² − r_i²|d|² = 0, and a random real chart c·d = 1 (the
//   spin and slide of the line are not unknowns: a pose encoding would leave them free).
// Each family has a generic complex member (random coefficients of the same monomials) that is
// the cached start system of `phc -p`.
#include <complex>
#include <map>
#include <string>
#include <vector>

#include "relpos/core/problem.hpp"

namespace relpos::bench {

enum class Family { kPointDistances, kLineDistances };

struct PolySystem {
  std::vector<std::string> variables;
  // Each polynomial: exponent vector (one entry per variable) → coefficient.
  std::vector<std::map<std::vector<int>, std::complex<double>>> equations;
};

// The family of a spec, or false when it is neither (every constraint a point-point distance
// on six legs, or four point(fixed)-line(mobile) distances).
bool familyOf(const Problem& p, Family* family);

PolySystem targetSystem(const Problem& p, Family family);
// A generic complex member of the family, from a fixed seed.
PolySystem genericMember(Family family, unsigned seed);

// PHCpack's input format: "N N" then one polynomial per equation, ';'-terminated.
std::string phcText(const PolySystem& s);

// A real solution of the family's unknowns, as the pose (point distances) or a pose whose mobile
// line is the solved line (line distances: identity rotation when the mobile line is along z).
bool poseOfSolution(const Problem& p, Family family, const std::vector<double>& x, Isometry3d* X);

}  // namespace relpos::bench
