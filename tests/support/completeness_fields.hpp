#pragma once
// The numeric stage adds Branch::exact, Branch::certified {radius, angle} and Solution::complete
// (issue 15, docs/spec.md §2). These tests are written against that API but must build before it
// lands: each accessor reads the field when the type has it and says so when it does not.
#include <optional>
#include <type_traits>
#include <utility>

#include "relpos/core/solution.hpp"

namespace relpos::test {

template <class B, class = void>
struct HasCertificate : std::false_type {};
template <class B>
struct HasCertificate<B, std::void_t<decltype(std::declval<const B&>().exact),
                                     decltype(std::declval<const B&>().certified.radius),
                                     decltype(std::declval<const B&>().certified.angle)>>
    : std::true_type {};

template <class S, class = void>
struct HasComplete : std::false_type {};
template <class S>
struct HasComplete<S, std::void_t<decltype(std::declval<const S&>().complete)>> : std::true_type {};

struct BranchProof {
  bool exact = true;
  double radius = 0.0, angle = 0.0;
};

// The branch's exact flag and certificate; nullopt before the fields exist.
template <class B = Branch>
std::optional<BranchProof> proofOf(const B& b) {
  if constexpr (HasCertificate<B>::value) {
    return BranchProof{b.exact, b.certified.radius, b.certified.angle};
  } else {
    return std::nullopt;
  }
}

// Solution::complete; nullopt before the field exists.
template <class S = Solution>
std::optional<bool> completeOf(const S& s) {
  if constexpr (HasComplete<S>::value) {
    return static_cast<bool>(s.complete);
  } else {
    return std::nullopt;
  }
}

}  // namespace relpos::test
