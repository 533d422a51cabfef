#pragma once
// Deterministic random numbers with the same sequence on every platform and standard library
// (std::normal_distribution's algorithm is unspecified): SplitMix64, uniform, Box–Muller.
#include <cmath>
#include <cstdint>
#include <string>

#include "relpos/complete/family.hpp"

namespace relpos::complete::detail {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double gaussian() {
    const double u = 1.0 - uniform(), v = uniform();  // u in (0, 1]
    return std::sqrt(-2.0 * std::log(u)) * std::cos(6.283185307179586 * v);
  }
  Complex complexGaussian() {
    const double re = gaussian();
    return {re, gaussian()};
  }

 private:
  std::uint64_t state_;
};

// FNV-1a: a hash of a signature that is the same on every run (std::hash need not be).
inline std::uint64_t stableHash(const std::string& s) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char ch : s) h = (h ^ ch) * 0x100000001b3ull;
  return h;
}

inline std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b) {
  return SplitMix64(a ^ (b * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull)).next();
}

}  // namespace relpos::complete::detail
