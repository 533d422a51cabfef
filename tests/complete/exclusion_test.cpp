// The interval branch and prune behind `complete` (complete/src/exclusion.hpp), on systems whose
// real roots are known in closed form: proven exactly when every real root in the box is among
// the known ones, never with a root left out, a curve of roots or a singular root.
#include "exclusion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

namespace relpos::complete::detail {
namespace {

// c · x_vars…, one term of an equation.
struct T {
  double c;
  std::vector<int> vars;
};

struct System {
  SystemShape shape;
  std::vector<Interval> coefficients;
};

System systemOf(const std::vector<std::vector<T>>& equations) {
  System s;
  s.shape.variables = static_cast<int>(equations.size());
  std::map<std::vector<int>, int> index;
  for (std::size_t k = 0; k < equations.size(); ++k)
    for (const T& t : equations[k]) {
      auto it = index.find(t.vars);
      if (it == index.end()) {
        it = index.emplace(t.vars, static_cast<int>(s.shape.monomials.size())).first;
        Monomial m;
        m.degree = static_cast<std::uint8_t>(t.vars.size());
        for (std::size_t i = 0; i < t.vars.size(); ++i) m.vars[i] = static_cast<std::uint8_t>(t.vars[i]);
        s.shape.monomials.push_back(m);
      }
      s.shape.terms.push_back({static_cast<std::uint16_t>(k), static_cast<std::uint16_t>(it->second)});
      s.coefficients.push_back(Interval(t.c));
    }
  return s;
}

RealBox box(std::vector<double> lo, std::vector<double> hi) {
  RealBox b;
  b.lo = Eigen::Map<RVec>(lo.data(), static_cast<Eigen::Index>(lo.size()));
  b.hi = Eigen::Map<RVec>(hi.data(), static_cast<Eigen::Index>(hi.size()));
  return b;
}

// A box of radius r about a point (holding the exact root when r is above its rounding).
RealBox around(std::vector<double> x, double r) {
  std::vector<double> lo = x, hi = x;
  for (std::size_t i = 0; i < x.size(); ++i) lo[i] -= r, hi[i] += r;
  return box(lo, hi);
}

const RealBox kSquare = box({-2.0, -2.0}, {2.0, 2.0});

// The unit circle and the line y = x / 2: two real roots ±(2, 1)/√5.
System circleAndLine() {
  return systemOf({{{1.0, {0, 0}}, {1.0, {1, 1}}, {-1.0, {}}}, {{1.0, {1}}, {-0.5, {0}}}});
}
std::vector<RealBox> circleAndLineRoots() {
  const double x = 2.0 / std::sqrt(5.0);
  return {around({x, x / 2}, 1e-12), around({-x, -x / 2}, 1e-12)};
}

TEST(Exclusion, ProvenWhenEveryRealRootIsKnown) {
  const System s = circleAndLine();
  for (const std::vector<bool>& secondary : {std::vector<bool>{}, std::vector<bool>{false, true}}) {
    const ExclusionResult r = excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare,
                                                  circleAndLineRoots(), secondary);
    EXPECT_TRUE(r.proven) << r.why;
    EXPECT_GT(r.boxes, 0);
  }
}

TEST(Exclusion, ARootLeftOutIsFound) {
  const System s = circleAndLine();
  const std::vector<RealBox> one = {circleAndLineRoots()[0]};
  const ExclusionResult r = excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, one, {});
  EXPECT_FALSE(r.proven);
  EXPECT_NE(r.why.find("not found"), std::string::npos) << r.why;
  EXPECT_FALSE(excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, {}, {}).proven);
}

TEST(Exclusion, NoRealRootIsProvenWithNoneKnown) {
  // x² + y² + 1 = 0 has no real point; x² + y² = 9 misses the box [-2, 2]².
  for (const double c : {1.0, -9.0}) {
    const System s = systemOf({{{1.0, {0, 0}}, {1.0, {1, 1}}, {c, {}}}, {{1.0, {1}}, {-1.0, {0}}}});
    const ExclusionResult r = excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, {}, {});
    EXPECT_TRUE(r.proven) << c << ": " << r.why;
  }
}

TEST(Exclusion, ACurveOfRootsIsNeverProven) {
  // The second equation is twice the first: the whole circle.
  const System s =
      systemOf({{{1.0, {0, 0}}, {1.0, {1, 1}}, {-1.0, {}}}, {{2.0, {0, 0}}, {2.0, {1, 1}}, {-2.0, {}}}});
  ExclusionOptions o;
  o.max_boxes = 20000;
  const ExclusionResult r =
      excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, circleAndLineRoots(), {}, {}, o);
  EXPECT_FALSE(r.proven);
}

TEST(Exclusion, ASingularRootIsNeverProven) {
  // The circle and its tangent y = 1: a double root at (0, 1), known or not.
  const System s = systemOf({{{1.0, {0, 0}}, {1.0, {1, 1}}, {-1.0, {}}}, {{1.0, {1}}, {-1.0, {}}}});
  for (const std::vector<RealBox>& known : {std::vector<RealBox>{}, {around({0.0, 1.0}, 1e-9)}})
    EXPECT_FALSE(excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, known, {}).proven);
}

// The proof holds for every system the coefficient enclosures hold. y = [0.499, 0.5] x: every
// member meets the circle twice, once in each known root's uniqueness box: proven. y = c with c
// in [0.999, 1.001]: members below 1 meet it twice, 1 is tangent, above 1 none: the two roots
// of c = 0.999 cannot be proven to be all of every member's.
TEST(Exclusion, CoefficientEnclosuresCount) {
  System s = circleAndLine();
  s.coefficients.back() = Interval(-0.5, -0.499);
  EXPECT_TRUE(excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, circleAndLineRoots(),
                                  {})
                  .proven);
  System t = systemOf({{{1.0, {0, 0}}, {1.0, {1, 1}}, {-1.0, {}}}, {{1.0, {1}}, {-1.0, {}}}});
  t.coefficients.back() = Interval(-1.001, -0.999);
  const double x = std::sqrt(1.0 - 0.999 * 0.999);
  const std::vector<RealBox> known = {around({x, 0.999}, 1e-12), around({-x, 0.999}, 1e-12)};
  EXPECT_FALSE(excludeUnknownRoots(t.shape, t.coefficients.data(), kSquare, known, {}).proven);
}

// The circle and the line are symmetric under (x, y) ↦ (−x, −y): half the square suffices, as
// long as the mirror image of every known root is known too.
TEST(Exclusion, ASymmetryHalvesTheDomainButNotTheRoots) {
  const System s = circleAndLine();
  const RealBox half = box({-0.01, -2.0}, {2.0, 2.0});
  const std::vector<int> negated = {0, 1};
  const ExclusionResult both = excludeUnknownRoots(s.shape, s.coefficients.data(), half,
                                                   circleAndLineRoots(), {}, negated);
  EXPECT_TRUE(both.proven) << both.why;
  const ExclusionResult full = excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare,
                                                   circleAndLineRoots(), {});
  EXPECT_LE(both.boxes, full.boxes);
  // The half holds one root only, but its mirror image is missing from the list.
  const std::vector<RealBox> one = {circleAndLineRoots()[0]};
  const ExclusionResult r =
      excludeUnknownRoots(s.shape, s.coefficients.data(), half, one, {}, negated);
  EXPECT_FALSE(r.proven);
  EXPECT_NE(r.why.find("mirror"), std::string::npos) << r.why;
}

TEST(Exclusion, SameAnswerEveryRun) {
  const System s = circleAndLine();
  const ExclusionResult a =
      excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, circleAndLineRoots(), {});
  const ExclusionResult b =
      excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, circleAndLineRoots(), {});
  EXPECT_EQ(a.proven, b.proven);
  EXPECT_EQ(a.boxes, b.boxes);
}

TEST(Exclusion, GivesUpWithinItsBudget) {
  const System s = circleAndLine();
  ExclusionOptions o;
  o.max_boxes = 1;
  const ExclusionResult r =
      excludeUnknownRoots(s.shape, s.coefficients.data(), kSquare, circleAndLineRoots(), {}, {}, o);
  EXPECT_FALSE(r.proven);
  EXPECT_LE(r.boxes, 2);
  EXPECT_NE(r.why.find("gave up"), std::string::npos) << r.why;
}

}  // namespace
}  // namespace relpos::complete::detail
