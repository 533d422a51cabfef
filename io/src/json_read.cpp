#include "json_read.hpp"

#include <charconv>
#include <memory>
#include <string>
#include <unordered_set>

#include "json_path.hpp"
#include "json_scan.hpp"
#include "utf8.hpp"

namespace relpos::detail {
namespace {

namespace dom = simdjson::dom;

// One container being walked by checkKeys.
struct Frame {
  bool object;
  dom::object::iterator member, members_end;
  dom::array::iterator element, elements_end;
  std::size_t index = 0;       // of the next element (arrays)
  std::string_view child_key;  // of the member being walked (objects)
  std::size_t first_key = 0;   // its keys so far are keys[first_key...] (a short object)
  std::unique_ptr<std::unordered_set<std::string_view>> seen;  // its keys so far (a long one)
};

// What a thread keeps from one document to the next: the parser's buffers and the walk's
// stacks (no allocation per spec).
struct ThreadState {
  dom::parser parser = newParser();
  std::vector<Frame> stack;
  std::vector<std::string_view> keys;

  static dom::parser newParser() {
    dom::parser p;
    // simdjson counts a scalar inside the deepest container as one level more than relpos does:
    // its own limit is set a little above relpos's, which checkKeys applies (kMaxJsonDepth).
    if (p.allocate(std::size_t{1} << 16, kMaxJsonDepth + 8) != simdjson::SUCCESS) {
      // Out of memory: parse() retries the allocation (with simdjson's default depth).
    }
    return p;
  }
  // A parser keeps the buffers of the largest document it has read (about ten times its size):
  // after a huge one, a batch's threads go back to small buffers for the usual specs.
  void fitTo(std::size_t length) {
    constexpr std::size_t kKept = std::size_t{1} << 22;  // 4 MiB of text
    if (parser.capacity() > kKept && length <= kKept) parser = newParser();
  }
};

// Not inlined: in a shared library every use of a thread_local's address is a call to
// __tls_get_addr, which GCC repeats at each use rather than keeping the address (47 calls in
// readJson, 11% of a parse). Out of line, it is one call per document.
[[gnu::noinline]] ThreadState& threadState() {
  thread_local ThreadState state;
  return state;
}

// The text with each integer too wide for 64 bits rewritten as the double it denotes, so that
// simdjson reads it: its shortest round-trip digits as an integer mantissa and an exponent
// ("12345678901234568e13"), padded with spaces to the token's length (positions do not move).
// The form always fits: an integer of n ≥ 19 digits has a mantissa of at most 17 digits, so the
// exponent is at least n - 17 ≥ 2 and takes fewer characters than the digits it stands for.
bool widenIntegers(std::string_view text,
                   const std::vector<std::pair<std::size_t, std::size_t>>& spans,
                   std::string* out) {
  out->assign(text);
  for (const auto& [begin, end] : spans) {
    const double v = jsonNumberValue(text.substr(begin, end - begin));
    char buf[40];
    const auto written = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    const std::string_view sci(buf, static_cast<std::size_t>(written.ptr - buf));  // -d.ddde+XX
    const std::size_t e = sci.find('e'), point = sci.find('.');
    std::string mantissa;
    for (char c : sci.substr(0, e))
      if (c != '.') mantissa += c;
    int exponent = 0;
    std::string_view exp_text = sci.substr(e + 1);
    if (!exp_text.empty() && exp_text[0] == '+') exp_text.remove_prefix(1);
    std::from_chars(exp_text.data(), exp_text.data() + exp_text.size(), exponent);
    if (point != std::string_view::npos) exponent -= static_cast<int>(e - point - 1);
    std::string form = mantissa + "e" + std::to_string(exponent);
    if (form.size() > end - begin) return false;  // (not reached: see above)
    form.resize(end - begin, ' ');
    out->replace(begin, end - begin, form);
  }
  return true;
}

}  // namespace

bool checkKeys(dom::element value, const std::string& value_path, std::size_t depth_above,
               std::vector<Diagnostic>* errors) {
  constexpr std::size_t kShort = 16;
  ThreadState& state = threadState();
  std::vector<Frame>& stack = state.stack;
  std::vector<std::string_view>& keys = state.keys;
  stack.clear();
  keys.clear();
  auto path = [&] {
    std::string p = value_path;
    for (const Frame& f : stack) {
      if (f.object)
        appendPathKey(p, f.child_key);
      else
        appendPathIndex(p, f.index - 1);
    }
    return p;
  };
  // Pushes a container; false when it is one level too deep.
  auto enter = [&](dom::element e) {
    const dom::element_type t = e.type();
    if (t != dom::element_type::OBJECT && t != dom::element_type::ARRAY) return true;
    if (depth_above + stack.size() == kMaxJsonDepth) return false;
    Frame& f = stack.emplace_back();
    f.object = t == dom::element_type::OBJECT;
    if (f.object) {
      const dom::object obj = e.get_object().value_unsafe();
      f.member = obj.begin(), f.members_end = obj.end();
      f.first_key = keys.size();
      if (obj.size() > kShort) {
        f.seen = std::make_unique<std::unordered_set<std::string_view>>();
        f.seen->reserve(obj.size());
      }
    } else {
      const dom::array arr = e.get_array().value_unsafe();
      f.element = arr.begin(), f.elements_end = arr.end();
    }
    return true;
  };
  if (!enter(value)) return false;
  while (!stack.empty()) {
    Frame& f = stack.back();
    dom::element child;
    if (f.object) {
      if (f.member == f.members_end) {
        keys.resize(f.first_key);
        stack.pop_back();
        continue;
      }
      f.child_key = f.member.key();
      bool duplicate = false;
      if (f.seen) {
        duplicate = !f.seen->insert(f.child_key).second;
      } else {
        for (std::size_t k = f.first_key; k < keys.size() && !duplicate; ++k)
          duplicate = keys[k] == f.child_key;
        keys.push_back(f.child_key);
      }
      if (duplicate)
        errors->push_back(
            {escapeForMessage(path()), "duplicate key (each key may appear once in an object)"});
      child = f.member.value();
      ++f.member;
    } else {
      if (f.element == f.elements_end) {
        stack.pop_back();
        continue;
      }
      child = *f.element;
      ++f.element;
      ++f.index;
    }
    if (!enter(child)) return false;
  }
  return true;
}

JsonRead readJson(std::string_view text) {
  JsonRead r;
  ThreadState& state = threadState();
  state.fitTo(text.size());
  dom::parser& parser = state.parser;
  // simdjson needs its input padded: parse() copies it into the parser's own padded buffer
  // (kept between calls). An empty view may have no data at all.
  const char* data = text.empty() ? "" : text.data();
  dom::element root;
  simdjson::error_code error = parser.parse(data, text.size()).get(root);
  if (error) {
    JsonScan scan = scanJson(text);
    if (!scan.errors.empty()) {
      r.errors = std::move(scan.errors);
      return r;
    }
    std::string widened;
    if (!scan.wide_integers.empty() && widenIntegers(text, scan.wide_integers, &widened))
      error = parser.parse(widened.data(), widened.size()).get(root);
    if (error) {  // what simdjson refuses and the scan does not explain (a text beyond 4 GiB)
      r.errors.push_back(
          {"", std::string("cannot read the JSON: ") + simdjson::error_message(error)});
      return r;
    }
  }
  r.root = root;
  return r;
}

std::vector<Diagnostic> tooDeep(std::string_view text) {
  std::vector<Diagnostic> errors = scanJson(text).errors;
  if (errors.empty())  // (not reached: the scan applies the same limit)
    errors.push_back({"", "too deeply nested: more than " + std::to_string(kMaxJsonDepth) +
                              " arrays and objects inside each other"});
  return errors;
}

}  // namespace relpos::detail
