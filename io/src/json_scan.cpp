#include "json_scan.hpp"

#include <locale.h>  // newlocale (POSIX)
#include <simdjson.h>
#include <stdlib.h>  // strtod_l (glibc)

#include <cmath>
#include <cstdlib>

#include "json_path.hpp"
#include "utf8.hpp"

namespace relpos::detail {

bool isJsonNumber(std::string_view t, bool* integral) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i > start;
  };
  if (i < t.size() && t[i] == '-') ++i;
  if (i < t.size() && t[i] == '0')
    ++i;
  else if (!digits())
    return false;
  *integral = true;
  if (i < t.size() && t[i] == '.') {
    ++i;
    *integral = false;
    if (!digits()) return false;
  }
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    *integral = false;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == t.size();
}

double jsonNumberValue(std::string_view token) {
  // strtod is correctly rounded in glibc and gives ±HUGE_VAL past the range (and the exact
  // subnormal or zero below it); the "C" locale makes '.' the decimal point whatever the
  // program's locale.
  static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  const std::string nul_terminated(token);
  if (c_locale == static_cast<locale_t>(nullptr))  // (no memory for it: the program's locale)
    return std::strtod(nul_terminated.c_str(), nullptr);
  return strtod_l(nul_terminated.c_str(), nullptr, c_locale);
}

namespace {

// "line L, column C" of byte offsets given in increasing order, counted from where the last
// one was (a scan may report many numbers on one 3 MB line: counting from the line's start each
// time would be quadratic). Columns count characters from 1; each byte of an ill-formed UTF-8
// sequence counts as one (it is shown as one \xHH).
class LineCounter {
 public:
  explicit LineCounter(std::string_view text) : text_(text) {}
  std::string at(std::size_t offset) {
    while (at_ < offset && at_ < text_.size()) {
      if (text_[at_] == '\n') {
        ++line_, column_ = 1, ++at_;
        continue;
      }
      const Utf8Step step = utf8Step(text_.substr(at_));
      at_ += step.length;
      column_ += step.valid ? 1 : step.length;
    }
    return "line " + std::to_string(line_) + ", column " + std::to_string(column_);
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0, line_ = 1, column_ = 1;
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isWordChar(char c) {
  return isDigit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// A key as the document holds it: its escapes decoded (by simdjson: a string is a JSON text).
std::string unescapedKey(std::string_view quoted) {
  if (quoted.find('\\') == std::string_view::npos)
    return std::string(quoted.substr(1, quoted.size() - 2));
  thread_local simdjson::dom::parser parser;
  std::string_view key;
  if (parser.parse(quoted.data(), quoted.size()).get_string().get(key) != simdjson::SUCCESS)
    return std::string(quoted);  // (the scan has checked the string: not reached)
  return std::string(key);
}

// Echoed tokens are cut: a number may be a megabyte of digits.
std::string excerpt(std::string_view token) {
  constexpr std::size_t kMax = 40;
  return token.size() <= kMax ? std::string(token) : std::string(token.substr(0, kMax)) + "...";
}

class Scanner {
 public:
  explicit Scanner(std::string_view text) : t_(text), lines_(text) {}

  JsonScan run() {
    walk();
    return std::move(out_);
  }

 private:
  enum class State { kValue, kFirstKeyOrClose, kFirstValueOrClose, kAfterValue };
  struct Level {
    bool object;
    std::string_view key;  // the current member's key, quoted as in the text
    std::size_t index;     // the current element's index
  };

  // To the end of the document, or false at the first error.
  bool walk() {
    State state = State::kValue;
    for (;;) {
      skipSpace();
      switch (state) {
        case State::kValue:
          if (end()) return fail(i_, "expected a value, got the end of the text");
          if (t_[i_] == '{' || t_[i_] == '[') {
            if (stack_.size() == kMaxJsonDepth) return tooDeep(i_);
            const bool object = t_[i_++] == '{';
            stack_.push_back({object, {}, 0});
            state = object ? State::kFirstKeyOrClose : State::kFirstValueOrClose;
            break;
          }
          if (!scalar()) return false;
          state = State::kAfterValue;
          break;
        case State::kFirstKeyOrClose:
          if (!end() && t_[i_] == '}') {
            close();
            state = State::kAfterValue;
            break;
          }
          if (!key("expected a key (a string) or '}'")) return false;
          state = State::kValue;
          break;
        case State::kFirstValueOrClose:
          if (!end() && t_[i_] == ']') {
            close();
            state = State::kAfterValue;
          } else {
            state = State::kValue;
          }
          break;
        case State::kAfterValue: {
          if (stack_.empty()) {
            if (!end())
              return fail(i_,
                          "expected the end of the text after the document, got " + describe(i_));
            return true;
          }
          Level& top = stack_.back();
          const char close_char = top.object ? '}' : ']';
          const std::string expected = std::string("expected ',' or '") + close_char + "', got ";
          if (end()) return fail(i_, expected + describe(i_));
          if (t_[i_] == close_char) {
            close();
            break;
          }
          if (t_[i_] != ',') return fail(i_, expected + describe(i_));
          ++i_;
          if (top.object) {
            skipSpace();
            if (!key("expected a key (a string)")) return false;
          } else {
            ++top.index;
          }
          state = State::kValue;
          break;
        }
      }
    }
  }

  bool end() const { return i_ >= t_.size(); }
  void skipSpace() {
    while (!end() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\r' || t_[i_] == '\t')) ++i_;
  }
  void close() {
    stack_.pop_back();
    ++i_;
  }
  // Records the syntax error at `at`; false, to end the walk.
  bool fail(std::size_t at, const std::string& what) {
    out_.errors.push_back(
        {"", "malformed JSON at " + lines_.at(at) + ": " + escapeForMessage(what)});
    return false;
  }
  bool tooDeep(std::size_t at) {
    out_.errors.push_back({"", "too deeply nested at " + lines_.at(at) + ": more than " +
                                   std::to_string(kMaxJsonDepth) +
                                   " arrays and objects inside each other"});
    return false;
  }

  // What is at `at`, for "got ...": a word, one character, or the end.
  std::string describe(std::size_t at) const {
    if (at >= t_.size()) return "the end of the text";
    std::size_t n = 0;
    while (at + n < t_.size() && n < 24 && isWordChar(t_[at + n])) ++n;
    if (n == 0) n = utf8Step(t_.substr(at)).length;
    return "'" + std::string(t_.substr(at, n)) + "'";
  }

  // The JSON path of the value being read.
  std::string path() const {
    std::string p;
    for (const Level& l : stack_) {
      if (l.object)
        appendPathKey(p, unescapedKey(l.key));
      else
        appendPathIndex(p, l.index);
    }
    return p;
  }

  // A member's key and its colon.
  bool key(const char* expected) {
    if (end() || t_[i_] != '"') return fail(i_, std::string(expected) + ", got " + describe(i_));
    const std::size_t start = i_;
    if (!string()) return false;
    stack_.back().key = t_.substr(start, i_ - start);
    skipSpace();
    if (end() || t_[i_] != ':') return fail(i_, "expected ':' after the key, got " + describe(i_));
    ++i_;
    return true;
  }

  bool scalar() {
    const char c = t_[i_];
    if (c == '"') return string();
    if (c == '-' || isDigit(c)) return number();
    for (std::string_view word : {"true", "false", "null"})
      if (t_.substr(i_, word.size()) == word) {
        i_ += word.size();
        return true;
      }
    return fail(i_, "expected a value, got " + describe(i_));
  }

  bool hex4(std::size_t at, unsigned* v) const {
    if (at + 4 > t_.size()) return false;
    *v = 0;
    for (std::size_t k = at; k < at + 4; ++k) {
      const char h = t_[k];
      const unsigned d = isDigit(h)             ? unsigned(h - '0')
                         : h >= 'a' && h <= 'f' ? unsigned(h - 'a' + 10)
                         : h >= 'A' && h <= 'F' ? unsigned(h - 'A' + 10)
                                                : 16u;
      if (d == 16) return false;
      *v = *v * 16 + d;
    }
    return true;
  }

  bool string() {
    const std::size_t open = i_++;
    for (;;) {
      if (end()) return fail(open, "unterminated string (no closing '\"')");
      const auto c = static_cast<unsigned char>(t_[i_]);
      if (c == '"') {
        ++i_;
        return true;
      }
      if (c == '\\') {
        if (!escape()) return false;
      } else if (c < 0x20) {
        return fail(i_, "control character '" + std::string(1, static_cast<char>(c)) +
                            "' in a string (write it as an escape)");
      } else if (c >= 0x80) {
        const Utf8Step step = utf8Step(t_.substr(i_));
        if (!step.valid)
          return fail(
              i_, "invalid UTF-8 '" + std::string(t_.substr(i_, step.length)) + "' in a string");
        i_ += step.length;
      } else {
        ++i_;
      }
    }
  }

  // The escape at i_ (a backslash); a \u escape of a UTF-16 surrogate must be a pair.
  bool escape() {
    const std::size_t at = i_;
    if (at + 1 >= t_.size()) return fail(at, "unterminated string (no closing '\"')");
    const char e = t_[at + 1];
    if (e != 'u') {
      if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos)
        return fail(at, "invalid escape '\\" +
                            std::string(t_.substr(at + 1, utf8Step(t_.substr(at + 1)).length)) +
                            "' in a string");
      i_ += 2;
      return true;
    }
    unsigned cp = 0, low = 0;
    if (!hex4(at + 2, &cp))
      return fail(at, "invalid escape '" + std::string(t_.substr(at, 6)) +
                          "' in a string (\\u takes four hexadecimal digits)");
    if (cp >= 0xDC00 && cp <= 0xDFFF)
      return fail(at,
                  "unpaired UTF-16 surrogate '" + std::string(t_.substr(at, 6)) + "' in a string");
    if (cp >= 0xD800 && cp <= 0xDBFF) {
      const bool paired =
          t_.substr(at + 6, 2) == "\\u" && hex4(at + 8, &low) && low >= 0xDC00 && low <= 0xDFFF;
      if (!paired)
        return fail(
            at, "unpaired UTF-16 surrogate '" + std::string(t_.substr(at, 6)) + "' in a string");
      i_ += 12;
      return true;
    }
    i_ += 6;
    return true;
  }

  bool number() {
    const std::size_t start = i_;
    while (!end() && (isDigit(t_[i_]) || t_[i_] == '-' || t_[i_] == '+' || t_[i_] == '.' ||
                      t_[i_] == 'e' || t_[i_] == 'E'))
      ++i_;
    const std::string_view token = t_.substr(start, i_ - start);
    bool integral = false;
    if (!isJsonNumber(token, &integral))
      return fail(start, "invalid number '" + excerpt(token) + "'");
    if (integral && fitsIn64Bits(token)) return true;  // simdjson reads these itself
    if (std::isinf(jsonNumberValue(token))) {
      out_.errors.push_back({escapeForMessage(path()), "number out of the range of a double '" +
                                                           excerpt(token) + "' (" +
                                                           lines_.at(start) + ")"});
    } else if (integral) {
      out_.wide_integers.emplace_back(start, i_);
    }
    return true;
  }

  // Whether an integer token is within int64 (negative) or uint64 (otherwise), as simdjson needs.
  static bool fitsIn64Bits(std::string_view token) {
    const bool negative = token[0] == '-';
    const std::string_view digits = token.substr(negative ? 1 : 0);
    const std::string_view limit = negative ? "9223372036854775808" : "18446744073709551615";
    return digits.size() < limit.size() || (digits.size() == limit.size() && digits <= limit);
  }

  std::string_view t_;
  std::size_t i_ = 0;
  LineCounter lines_;
  std::vector<Level> stack_;
  JsonScan out_;
};

}  // namespace

JsonScan scanJson(std::string_view text) { return Scanner(text).run(); }

}  // namespace relpos::detail
