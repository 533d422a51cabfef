#include "fast_json.hpp"

#include <charconv>

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

void FastJson::skipSpace() {
  while (pos_ < text_.size() &&
         (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\t' || text_[pos_] == '\r'))
    ++pos_;
}

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

// A number in JSON's grammar: -? (0 | [1-9][0-9]*) (. [0-9]+)? ([eE] [+-]? [0-9]+)?
bool FastJson::number(double* out) {
  const std::size_t start = pos_;
  auto digit = [&] { return pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9'; };
  auto digits = [&] {
    if (!digit()) return false;
    while (digit()) ++pos_;
    return true;
  };
  if (pos_ < text_.size() && text_[pos_] == '-') ++pos_;
  if (pos_ < text_.size() && text_[pos_] == '0') {
    ++pos_;
  } else if (!digits()) {
    return false;
  }
  if (pos_ < text_.size() && text_[pos_] == '.') {
    ++pos_;
    if (!digits()) return false;
  }
  if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
    ++pos_;
    if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
    if (!digits()) return false;
  }
  const char* first = text_.data() + start;
  const char* last = text_.data() + pos_;
  const auto r = std::from_chars(first, last, *out);
  // Out of range (nlohmann reports it) or not all read: not ours.
  if (r.ec != std::errc() || r.ptr != last) return false;
  // nlohmann keeps "-0" as the integer 0, which reads back as +0.0.
  if (*out == 0.0 &&
      std::string_view(first, pos_ - start).find_first_of(".eE") == std::string_view::npos)
    *out = 0.0;
  return true;
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
            if (nodes_[k].key == key) return -1;
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

const FastJson::Node& FastJson::Ref::node() const {
  static const Node null_node;
  return index_ < 0 ? null_node : doc_->nodes_[static_cast<std::size_t>(index_)];
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

std::int32_t FastJson::Ref::member(std::string_view key) const {
  if (!is_object()) return -1;
  for (std::int32_t k = node().first; k >= 0; k = doc_->nodes_[static_cast<std::size_t>(k)].next)
    if (doc_->nodes_[static_cast<std::size_t>(k)].key == key) return k;
  return -1;
}

FastJson::Ref FastJson::Ref::operator[](std::size_t i) const {
  if (!is_array()) return Ref(doc_, -1);
  std::int32_t k = node().first;
  for (; k >= 0 && i > 0; --i) k = doc_->nodes_[static_cast<std::size_t>(k)].next;
  return Ref(doc_, k);
}

FastJson::Iterator FastJson::Ref::begin() const {
  return Iterator(doc_, is_array() || is_object() ? node().first : -1);
}

FastJson::Iterator FastJson::Ref::end() const { return Iterator(doc_, -1); }

}  // namespace relpos::detail
