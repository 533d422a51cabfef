#pragma once
// The computation behind startSystem (its cache aside), with the Bézout limit of the
// total-degree cross-check as a parameter (tests run the other cross-check on small families).
#include <cstdint>
#include <memory>

#include "relpos/complete/fiber.hpp"

namespace relpos::complete::detail {

// Above max_bezout the count is cross-checked by a second monodromy instead.
std::unique_ptr<StartSystem> computeStartSystem(const Family& f, std::uint64_t max_bezout);

}  // namespace relpos::complete::detail
