// PMF App. IV Table IX: a point of object a on a line of object b and a point of b on a plane
// of a (mixed_roles.hpp).
#include "family.hpp"
#include "mixed_roles.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pl_planep_family {
using namespace detail;

void linePlane(const Fundamental& x, const Fundamental& y, const Tolerance& tol, RuleOutput& out,
               const void* /*context*/) {
  pointsOrLines(x, y, true, tol, out);
}

constexpr RuleCaseRow kCases[] = {
    {kPointsOrLines, "points-or-plane", "PMF App. IV Table IX, row 1"}};

}  // namespace pl_planep_family

constexpr RuleFamily families::pl_planep =
    family("pl+planep", "PMF App. IV Table IX", FundamentalKind::kPointLine,
           FundamentalKind::kPointPlane, &pl_planep_family::linePlane, pl_planep_family::kCases);

}  // namespace relpos::rules
