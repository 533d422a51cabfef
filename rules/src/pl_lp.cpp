// PMF App. IV Table VIII: a point of object a on a line of object b and a point of b on a line
// of a (mixed_roles.hpp).
#include "family.hpp"
#include "mixed_roles.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pl_lp_family {
using namespace detail;

void lineLine(const Fundamental& x, const Fundamental& y, const Tolerance& tol, RuleOutput& out,
              const void* /*context*/) {
  if (x.point_side == Side::kMobile) return pointsOrLines(x, y, false, tol, out);
  pointsOrLines(y, x, false, tol, out);
}

constexpr RuleCaseRow kCases[] = {
    {kPointsOrLines, "points-or-lines", "PMF App. IV Table VIII, row 1"}};

}  // namespace pl_lp_family

constexpr RuleFamily families::pl_lp =
    family("pl+lp", "PMF App. IV Table VIII", FundamentalKind::kPointLine,
           FundamentalKind::kPointLine, &pl_lp_family::lineLine, pl_lp_family::kCases);

}  // namespace relpos::rules
