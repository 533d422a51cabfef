#pragma once
// A compile-time fingerprint of data layouts and function signatures (FNV-1a, 64 bits), for the
// plugin ABI check (plugin_api.hpp): a plugin built against headers whose shared structs differ
// in any listed member's offset, size or alignment, or whose callbacks take other parameters,
// gets a different fingerprint and is refused. Portable across compilers of one ABI (it reads
// only sizes, alignments, offsets and type categories, never spelled type names).
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace relpos::abi {

inline constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

// Folds the 8 bytes of v into h, low byte first.
constexpr std::uint64_t fold(std::uint64_t h, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) {
    h ^= (v >> (8 * i)) & 0xff;
    h *= kFnvPrime;
  }
  return h;
}

template <typename... V>
constexpr std::uint64_t hash(V... values) {
  std::uint64_t h = kFnvOffset;
  ((h = fold(h, static_cast<std::uint64_t>(values))), ...);
  return h;
}

// A type as its category (reference, pointer, const), size and alignment.
template <typename T>
constexpr std::uint64_t typeCode() {
  using Bare = std::remove_reference_t<T>;
  using Pointee = std::remove_pointer_t<Bare>;
  constexpr std::uint64_t category =
      (std::is_lvalue_reference_v<T> ? 1 : 0) | (std::is_rvalue_reference_v<T> ? 2 : 0) |
      (std::is_pointer_v<Bare> ? 4 : 0) | (std::is_const_v<Bare> ? 8 : 0) |
      (std::is_const_v<Pointee> ? 16 : 0);
  if constexpr (std::is_void_v<Pointee> || std::is_function_v<Pointee>) {
    return hash(category, 0, 0);
  } else {
    return hash(category, sizeof(Pointee), alignof(Pointee));
  }
}

// A function pointer type as its arity, result and parameters, in order.
template <typename F>
struct Signature;
template <typename R, typename... Args>
struct Signature<R (*)(Args...)> {
  static constexpr std::uint64_t value = hash(sizeof...(Args), typeCode<R>(), typeCode<Args>()...);
};
template <typename R, typename... Args>
struct Signature<R (*)(Args...) noexcept> {
  static constexpr std::uint64_t value =
      hash(sizeof...(Args) + 1000, typeCode<R>(), typeCode<Args>()...);
};

}  // namespace relpos::abi

// One struct member: where it is, how large and how aligned. (offsetof on a struct that is not
// standard-layout, e.g. one holding a std::string, is conditionally supported; GCC and Clang
// support it for these, which have no virtual bases.)
#define RELPOS_ABI_MEMBER(T, m)                                     \
  ::relpos::abi::hash(offsetof(T, m), sizeof(std::declval<T&>().m), \
                      alignof(std::remove_reference_t<decltype(std::declval<T&>().m)>))
// A whole type: size and alignment.
#define RELPOS_ABI_TYPE(T) ::relpos::abi::hash(sizeof(T), alignof(T))
