#include "shortest_double.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace relpos::detail {
namespace {

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Four digits of d < 10^4 at `at`, leading zeros included.
void fourDigits(char* at, std::uint32_t d) {
  std::memcpy(at, kPairs + 2 * (d / 100), 2);
  std::memcpy(at + 2, kPairs + 2 * (d % 100), 2);
}

// Eight digits of d < 10^8 at `at`, leading zeros included.
void eightDigits(char* at, std::uint32_t d) {
  fourDigits(at, d / 10000);
  fourDigits(at + 4, d % 10000);
}

// How many decimal digits d has, for 0 < d < 10^17 (a shortest significand: at most 57 bits, so
// the guess below is at most 17): log10 from the bit length, then one compare.
int digitCount(std::uint64_t d) {
  static constexpr std::uint64_t kPowers[18] = {1,
                                                10,
                                                100,
                                                1000,
                                                10000,
                                                100000,
                                                1000000,
                                                10000000,
                                                100000000,
                                                1000000000,
                                                10000000000,
                                                100000000000,
                                                1000000000000,
                                                10000000000000,
                                                100000000000000,
                                                1000000000000000,
                                                10000000000000000,
                                                100000000000000000};
  const int guess = ((64 - __builtin_clzll(d)) * 1233) >> 12;  // 1233/4096 ≈ log10(2)
  return guess + (d >= kPowers[guess] ? 1 : 0);
}

// The 17 decimal digits of d < 10^17 (a double's shortest significand), leading zeros included,
// at `at`: fixed steps in 32-bit pieces, each four digits from a table of pairs. A digit at a time
// was a chain of 64-bit divisions and a loop of varying length; it cost more than finding them.
void seventeenDigits(char* at, std::uint64_t d) {
  const std::uint64_t high = d / 100000000;
  *at = static_cast<char>('0' + high / 100000000);
  eightDigits(at + 1, static_cast<std::uint32_t>(high % 100000000));
  eightDigits(at + 9, static_cast<std::uint32_t>(d % 100000000));
}

}  // namespace

char* writeShortestDouble(char* first, double v) {
  // 2^53: from there a double is an integer whose exact digits to_chars writes in the fixed form
  // (18446744073709551616, not 18446744073709552000).
  if (!std::isfinite(v) || std::abs(v) >= 9007199254740992.0)
    return std::to_chars(first, first + 24, v).ptr;
  // Pieces are copied at fixed sizes past their ends (the caller's 40 bytes of room) and the
  // places chosen by arithmetic, not branches: random signs, digit counts and magnitudes made
  // branches mispredict, which took longer than finding the digits.
  char* out = first;
  *out = '-';
  out += std::signbit(v) ? 1 : 0;
  if (v == 0.0) {
    *out++ = '0';
    return out;
  }
  // v = s·10^e with s the shortest significand (fmt 9's Dragonbox; detail is its only spelling of
  // it, and Debian 12 keeps fmt at 9.1).
  const auto dec = fmt::detail::dragonbox::to_decimal(std::abs(v));
  std::uint64_t s = dec.significand;
  int e = dec.exponent;
  while (s % 10 == 0) s /= 10, ++e;  // the shortest form has no trailing zeros
  // 20 zeros, then s's 17 digits (leading zeros included) ending at kEnd, then spare room: the
  // fixed form's "0.000ddd" reads its zeros from here, and every copy below stays inside.
  constexpr int kEnd = 37;
  char digits[64];
  std::memset(digits, '0', sizeof digits);  // (the spare room too: no copy reads unset bytes)
  seventeenDigits(digits + 20, s);
  const int n = digitCount(s);
  const char* const d = digits + kEnd - n;  // the first significant digit
  const int sci_exp = e + n - 1;            // v = d.ddd × 10^sci_exp
  const int abs_exp = sci_exp < 0 ? -sci_exp : sci_exp;
  // The two forms' lengths (the sign aside, the same in both): d[.ddd]e±XX, and the fixed form's
  // ddd000, dd.ddd or 0.000ddd.
  const int sci_len = n + (n > 1 ? 1 : 0) + 2 + (abs_exp >= 100 ? 3 : 2);
  const int fixed_len = e >= 0 ? n + e : (n + e > 0 ? n + 1 : 2 - e);
  if (fixed_len <= sci_len && e >= 0) {  // an integer below 2^53: at most 16 digits
    std::memcpy(out, d, 16);
    std::memset(out + n, '0', 16);
    return out + n + e;
  }
  if (fixed_len <= sci_len) {
    // The point falls after the digit at kEnd + e - 1; before it at least one digit ("0.").
    const int point = kEnd + e;
    const int whole_from = std::min(kEnd - n, point - 1);
    std::memcpy(out, digits + whole_from, 16);
    out += point - whole_from;
    *out++ = '.';
    std::memcpy(out, digits + point, 20);  // -e ≤ 20 digits: a longer fixed form loses to e±XX
    return out - e;
  }
  out[0] = d[0];
  out[1] = '.';
  std::memcpy(out + 2, d + 1, 16);
  out += n > 1 ? n + 1 : 1;
  *out++ = 'e';
  *out++ = sci_exp < 0 ? '-' : '+';
  // At least two digits (1e-07, 1e+05), three from 100.
  if (abs_exp >= 100) *out++ = static_cast<char>('0' + abs_exp / 100);
  std::memcpy(out, kPairs + 2 * (abs_exp % 100), 2);
  return out + 2;
}

}  // namespace relpos::detail
