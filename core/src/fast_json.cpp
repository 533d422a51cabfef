#include "fast_json.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>

namespace relpos::detail {
namespace {
// Deeper documents go to nlohmann (its own limit and messages).
constexpr int kMaxDepth = 64;
}  // namespace

bool FastJson::parse(std::string_view text) {
  text_ = text;
  pos_ = 0;
  depth_ = 0;
  nodes_.clear();
  if (value() != 0) return false;
  skipSpace();
  return pos_ == text_.size();
}

FastJson::Ref FastJson::root() const { return Ref(this, nodes_.empty() ? -1 : 0); }

// A string without escapes and of printable ASCII only (the rest is nlohmann's to decode).
bool FastJson::string(std::string_view* out) {
  const std::size_t start = ++pos_;  // after the opening quote
  while (pos_ < text_.size()) {
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c == '"') {
      *out = text_.substr(start, pos_ - start);
      ++pos_;
      return true;
    }
    if (c == '\\' || c < 0x20 || c >= 0x80) return false;
    ++pos_;
  }
  return false;
}

namespace {
// Eight ASCII digits at p as a number, or false (fast_float's SWAR test and conversion; x86 is
// little-endian). One digit at a time, the multiply-add chain was most of reading a number.
bool eightDigits(const char* p, std::uint64_t* value) {
  static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the SWAR digits assume little-endian");
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  if ((((v + 0x4646464646464646ull) | (v - 0x3030303030303030ull)) & 0x8080808080808080ull) != 0)
    return false;
  v -= 0x3030303030303030ull;
  v = v * 10 + (v >> 8);
  constexpr std::uint64_t kMask = 0x000000FF000000FFull;
  constexpr std::uint64_t kMul1 = 0x000F424000000064ull;  // 100 + (1000000 << 32)
  constexpr std::uint64_t kMul2 = 0x0000271000000001ull;  // 1 + (10000 << 32)
  *value = (((v & kMask) * kMul1) + (((v >> 16) & kMask) * kMul2)) >> 32;
  return true;
}
}  // namespace

// A number in JSON's grammar: -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
//
// Clinger's fast path while scanning: when the digits make an integer m ≤ 2^53 and the decimal
// exponent e has |e| ≤ 22, both m and 10^|e| are exact doubles, so m·10^e (or m/10^-e) rounds
// once, correctly: the double from_chars would give. Longer mantissas (most of the 17-digit
// numbers a program writes) and larger exponents go to from_chars.
bool FastJson::number(double* out) {
  const std::size_t start = pos_;
  const std::size_t n = text_.size();
  auto digit = [&] { return pos_ < n && text_[pos_] >= '0' && text_[pos_] <= '9'; };
  std::uint64_t m = 0;
  int kept = 0;                // digits in m (after its leading zeros)
  bool long_mantissa = false;  // more than 19 of them: from_chars decides
  int e10 = 0;                 // minus the fraction's digits, plus the exponent
  // A run of digits into m; in a fraction each also lowers the exponent.
  auto run = [&](bool fraction) {
    if (m == 0)
      while (pos_ < n && text_[pos_] == '0') ++pos_, e10 -= fraction ? 1 : 0;
    std::uint64_t eight;
    while (kept <= 11 && n - pos_ >= 8 && eightDigits(text_.data() + pos_, &eight)) {
      m = m * 100000000u + eight;
      kept += 8, pos_ += 8, e10 -= fraction ? 8 : 0;
    }
    for (; digit(); ++pos_) {
      if (kept < 19) {
        m = 10 * m + static_cast<std::uint64_t>(text_[pos_] - '0');
        ++kept, e10 -= fraction ? 1 : 0;
      } else {
        long_mantissa = true;  // (m and e10 no longer matter)
      }
    }
  };
  const bool negative = pos_ < n && text_[pos_] == '-';
  if (negative) ++pos_;
  if (pos_ < n && text_[pos_] == '0') {
    ++pos_;
  } else {
    if (!digit()) return false;
    run(false);
  }
  bool integral = true;
  if (pos_ < n && text_[pos_] == '.') {
    integral = false;
    ++pos_;
    if (!digit()) return false;
    run(true);
  }
  if (pos_ < n && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
    integral = false;
    ++pos_;
    const bool minus = pos_ < n && text_[pos_] == '-';
    if (pos_ < n && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
    if (!digit()) return false;
    int e = 0;
    while (digit()) e = std::min(e * 10 + (text_[pos_++] - '0'), 100000);
    e10 += minus ? -e : e;
  }
  // nlohmann keeps "-0" as the integer 0, which reads back as +0.0.
  if (m == 0 && !long_mantissa) {
    *out = negative && !integral ? -0.0 : 0.0;
    return true;
  }
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (!long_mantissa && m <= (std::uint64_t{1} << 53) && e10 >= -22 && e10 <= 22) {
    const double v = static_cast<double>(m);
    *out = e10 >= 0 ? v * kPow10[e10] : v / kPow10[-e10];
    if (negative) *out = -*out;
    return true;
  }
  const char* first = text_.data() + start;
  const char* last = text_.data() + pos_;
  const auto r = std::from_chars(first, last, *out);
  // Out of range (nlohmann reports it) or not all read: not ours.
  return r.ec == std::errc() && r.ptr == last;
}

// One value at pos_: its node index, or -1 when it is not read here.
std::int32_t FastJson::value() {
  skipSpace();
  if (pos_ >= text_.size()) return -1;
  const std::int32_t index = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  const char c = text_[pos_];
  auto literal = [&](std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  };
  if (c == '"') {
    nodes_[index].type = Type::kString;
    std::string_view s;
    if (!string(&s)) return -1;
    nodes_[index].text = s;
  } else if (c == '{' || c == '[') {
    const bool object = c == '{';
    nodes_[index].type = object ? Type::kObject : Type::kArray;
    if (++depth_ > kMaxDepth) return -1;
    ++pos_;
    skipSpace();
    const char close = object ? '}' : ']';
    std::int32_t last = -1;
    if (pos_ < text_.size() && text_[pos_] == close) {
      ++pos_;
    } else {
      for (;;) {
        std::string_view key;
        if (object) {
          skipSpace();
          if (pos_ >= text_.size() || text_[pos_] != '"' || !string(&key)) return -1;
          // Duplicate keys: nlohmann keeps the last value in the first place; not ours.
          for (std::int32_t k = nodes_[index].first; k >= 0; k = nodes_[k].next)
            if (sameKey(nodes_[k].key, key)) return -1;
          skipSpace();
          if (pos_ >= text_.size() || text_[pos_] != ':') return -1;
          ++pos_;
        }
        const std::int32_t child = value();
        if (child < 0) return -1;
        nodes_[child].key = key;
        (last < 0 ? nodes_[index].first : nodes_[last].next) = child;
        last = child;
        ++nodes_[index].count;
        skipSpace();
        if (pos_ >= text_.size()) return -1;
        if (text_[pos_] == ',') {
          ++pos_;
          continue;
        }
        if (text_[pos_] != close) return -1;
        ++pos_;
        break;
      }
    }
    --depth_;
  } else if (c == 't' || c == 'f') {
    nodes_[index].type = Type::kBoolean;
    nodes_[index].boolean = c == 't';
    if (!literal(c == 't' ? "true" : "false")) return -1;
  } else if (c == 'n') {
    if (!literal("null")) return -1;
  } else {
    nodes_[index].type = Type::kNumber;
    double v = 0.0;
    if (!number(&v)) return -1;
    nodes_[index].number = v;
  }
  return index;
}

const char* FastJson::Ref::type_name() const {
  switch (type()) {
    case Type::kNull:
      return "null";
    case Type::kBoolean:
      return "boolean";
    case Type::kNumber:
      return "number";
    case Type::kString:
      return "string";
    case Type::kArray:
      return "array";
    case Type::kObject:
      return "object";
  }
  return "null";
}

std::size_t FastJson::Ref::size() const {
  switch (type()) {
    case Type::kNull:
      return 0;
    case Type::kArray:
    case Type::kObject:
      return node().count;
    default:
      return 1;
  }
}

}  // namespace relpos::detail
