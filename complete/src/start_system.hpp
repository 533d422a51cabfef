#pragma once
// The computation behind startSystem (its cache aside), with the Bézout limit of the
// total-degree cross-check as a parameter (tests run the other cross-check on small families).
#include <cstdint>
#include <memory>

#include "relpos/complete/fiber.hpp"

namespace relpos::complete::detail {

// The Bézout limit startSystem uses (and the generator of the stored start systems).
inline constexpr std::uint64_t kDefaultMaxBezout = 4096;

// The most predictor-corrector steps a start system computed while solving may take (its
// monodromy loops; before issue 16's batch work, with the cross-check too): at most about 8 s on this machine (a step of an 8-unknown family
// with 300-600 terms costs about 13 µs; the random 2-4-constraint problems' families took
// 60,000–180,000 steps, four points at six distances (160 roots) 160,000–450,000, one family
// of a random 5-constraint problem over five million). A family needing
// more — thousands of roots, or paths that crawl — is not computed while solving (its answer
// would not be complete anyway: only a stored, trace-tested count proves that every root was
// found, docs/spec.md §8.5); the charts answer. Counted in steps, not seconds, so that the same
// problem gets the same answer on any machine.
inline constexpr std::uint64_t kSolvingStepBudget = 600000;

// Above max_bezout the count is cross-checked by a second monodromy instead.
// seed (0: the signature's stable hash, what startSystem uses) picks the generic member and the
// monodromy loops; another seed gives an independent computation of the same count.
// max_steps (0: no limit): predictor-corrector steps, the Krawczyk tests of the roots found
// counted as steps too (StartSystem::root_tests); past it the computation stops, with no roots
// and check "over the step budget".
// cross_check false: monodromy alone (check "monodromy"), what a solve computes (startSystem's
// cache, findStartSystem): on the 227 families of 20,000 random 2-4-constraint specs the
// cross-check never added a root to monodromy's, and took two thirds of the time (0.3-0.8 s a
// family); a solve never claims completeness from a computed start system anyway. Its
// monodromy tracks a fixed graph of members first, then three random loops that add nothing.
std::unique_ptr<StartSystem> computeStartSystem(const Family& f, std::uint64_t max_bezout,
                                                std::uint64_t seed = 0,
                                                std::uint64_t max_steps = 0,
                                                bool cross_check = true);

}  // namespace relpos::complete::detail
