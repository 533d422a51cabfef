// PMF App. IV Tables V and IX, p = 0 rows (generalised): a pinned mobile point and a point-plane
// coincidence of another point, a condition on the rotation alone (pinned.hpp).
#include <cmath>

#include "family.hpp"
#include "pinned.hpp"

namespace relpos::rules {
// Named, not anonymous: a unity source holds several families (rules/CMakeLists.txt).
namespace pp0_pplane_family {
using namespace detail;

enum Case { kIncompatible, kImplied, kAngle };

// The span `len` long (from the pin to the other point) at height h over a plane through the pin
// (its normal being the other vector): ∠ = acos(h / len).
void pinPlaneAngle(const Fundamental& pin, const Vector3d& u_m, const Vector3d& w_f, double h,
                   double len, const Tolerance& tol, RuleOutput& out) {
  if (std::abs(h) > len + tol.length) return out.fire(kIncompatible).incompatible(kOutOfReach);
  two(out.fire(kAngle), pin,
      withErr(Fundamental::angle(u_m, w_f, std::acos(clampUnit(h / len)), 0),
              heightAngleErr(h, len, tol)));
}

void pinnedWithPointPlane(const Fundamental& pin, const Fundamental& b, const Tolerance& tol,
                          RuleOutput& out) {
  if (!pinned(pin, tol)) return;
  if (b.point_side == Side::kMobile) {
    // (P_f + R u − c)·n = 0  <=>  R u · n = (c − P_f)·n.
    const Vector3d u = b.p - pin.p;
    const double h = (b.q - pin.q).dot(b.d), nu = u.norm();
    if (nu <= tol.length) return impliedOrIncompatible<Case>(tol.zeroLength(h), out);
    return pinPlaneAngle(pin, u / nu, b.d, h, nu, tol, out);
  }
  // Fixed Q_f on the mobile plane (c_m, n_m): (Q_f − P_f)·R n_m = (c_m − P_m)·n_m.
  const Vector3d w = b.p - pin.q;
  const double h = (b.q - pin.p).dot(b.d), nw = w.norm();
  if (nw <= tol.length) return impliedOrIncompatible<Case>(tol.zeroLength(h), out);
  pinPlaneAngle(pin, b.d, w / nw, h, nw, tol, out);
}

constexpr RuleCaseRow kCases[] = {
    {kIncompatible, "incompatible", "PMF App. IV Table V, row 1 with p = 0"},
    {kImplied, "implied", "PMF App. IV Table V, row 2 with p = 0"},
    {kAngle, "angle", "PMF App. IV Table V, rows 5 and 6 (generalised)"}};

}  // namespace pp0_pplane_family

constexpr RuleFamily families::pp0_pplane =
    family("pp0+pplane", "PMF App. IV Tables V and IX, p = 0 rows (generalised)",
           FundamentalKind::kPointPoint, FundamentalKind::kPointPlane,
           &pp0_pplane_family::withLengthErr<pp0_pplane_family::pinnedWithPointPlane>,
           pp0_pplane_family::kCases);

}  // namespace relpos::rules
