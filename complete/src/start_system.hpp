#pragma once
// The computation behind startSystem (its cache aside), with the Bézout limit of the
// total-degree cross-check as a parameter (tests run the other cross-check on small families).
#include <cstdint>
#include <memory>

#include "relpos/complete/fiber.hpp"

namespace relpos::complete::detail {

// The Bézout limit startSystem uses (and the generator of the stored start systems).
inline constexpr std::uint64_t kDefaultMaxBezout = 4096;

// Above max_bezout the count is cross-checked by a second monodromy instead.
// seed (0: the signature's stable hash, what startSystem uses) picks the generic member and the
// monodromy loops; another seed gives an independent computation of the same count.
std::unique_ptr<StartSystem> computeStartSystem(const Family& f, std::uint64_t max_bezout,
                                                std::uint64_t seed = 0);

}  // namespace relpos::complete::detail
