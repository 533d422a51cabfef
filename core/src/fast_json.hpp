#pragma once
// A small JSON reader for the spec parser's common case, with the slice of nlohmann's interface
// the parser uses (FastJson::Ref), so one parser serves both.
//
// Why: a batch parses one spec per line, and building nlohmann's document (a heap node per value,
// a heap string per key) cost more than solving and writing together. Here the values are nodes
// in one vector and strings are views into the text.
//
// It reads only what it can read exactly as nlohmann would: plain ASCII strings without escapes,
// numbers in strict JSON grammar, no duplicate keys. Anything else (including every malformed
// document) makes parse() return false, and the caller parses with nlohmann, which gives the
// same document or its usual error message.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace relpos::detail {

class FastJson {
 public:
  enum class Type : unsigned char { kNull, kBoolean, kNumber, kString, kArray, kObject };

  // Whether the text was read (false: leave it to nlohmann). The text must outlive the document.
  bool parse(std::string_view text);

  class Ref;
  class Iterator;
  Ref root() const;

 private:
  struct Node {
    Type type = Type::kNull;
    bool boolean = false;
    double number = 0.0;
    std::string_view text;               // a string's value
    std::string_view key;                // its key, for a member of an object
    std::int32_t first = -1, next = -1;  // first child; next sibling
    std::uint32_t count = 0;             // children
  };
  std::int32_t value();
  bool string(std::string_view* out);
  bool number(double* out);
  void skipSpace() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
  }
  const Node& at(std::int32_t i) const { return nodes_[static_cast<std::size_t>(i)]; }
  // Keys are a few letters: a loop beats a call to memcmp.
  static bool sameKey(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] != b[i]) return false;
    return true;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  std::vector<Node> nodes_;
};

// A value of the document, read like a const nlohmann::json.
class FastJson::Ref {
 public:
  Ref(const FastJson* doc, std::int32_t index) : doc_(doc), index_(index) {}
  bool is_null() const { return type() == Type::kNull; }
  bool is_boolean() const { return type() == Type::kBoolean; }
  bool is_number() const { return type() == Type::kNumber; }
  bool is_string() const { return type() == Type::kString; }
  bool is_array() const { return type() == Type::kArray; }
  bool is_object() const { return type() == Type::kObject; }
  const char* type_name() const;
  std::size_t size() const;
  bool empty() const { return size() == 0; }
  bool contains(std::string_view key) const { return member(key) >= 0; }
  // A missing key or index gives null (nlohmann's const operator[] must not be asked for one).
  // One overload for keys: a literal's length is then a compile-time constant, not a strlen call.
  Ref operator[](std::string_view key) const { return Ref(doc_, member(key)); }
  Ref operator[](std::size_t i) const;
  Ref operator[](int i) const { return (*this)[static_cast<std::size_t>(i)]; }
  template <typename T>
  T get() const;
  bool operator==(const char* s) const { return is_string() && node().text == s; }
  bool operator!=(const char* s) const { return !(*this == s); }
  bool operator==(int v) const { return is_number() && node().number == v; }
  bool operator!=(int v) const { return !(*this == v); }
  Iterator begin() const;
  Iterator end() const;

 private:
  friend class Iterator;
  const Node& node() const;
  Type type() const { return index_ < 0 ? Type::kNull : node().type; }
  std::int32_t member(std::string_view key) const;
  const FastJson* doc_;
  std::int32_t index_;
};

// Over an array's elements or an object's members (key() and value()).
class FastJson::Iterator {
 public:
  Iterator(const FastJson* doc, std::int32_t index) : doc_(doc), index_(index) {}
  Ref operator*() const { return Ref(doc_, index_); }
  Ref value() const { return Ref(doc_, index_); }
  std::string_view key() const { return doc_->at(index_).key; }
  Iterator& operator++() {
    index_ = doc_->at(index_).next;
    return *this;
  }
  bool operator!=(const Iterator& o) const { return index_ != o.index_; }
  bool operator==(const Iterator& o) const { return index_ == o.index_; }

 private:
  const FastJson* doc_;
  std::int32_t index_;
};

inline const FastJson::Node& FastJson::Ref::node() const {
  static const Node null_node;
  return index_ < 0 ? null_node : doc_->at(index_);
}

inline std::int32_t FastJson::Ref::member(std::string_view key) const {
  if (!is_object()) return -1;
  for (std::int32_t k = node().first; k >= 0; k = doc_->at(k).next)
    if (sameKey(doc_->at(k).key, key)) return k;
  return -1;
}

inline FastJson::Ref FastJson::Ref::operator[](std::size_t i) const {
  if (!is_array()) return Ref(doc_, -1);
  std::int32_t k = node().first;
  for (; k >= 0 && i > 0; --i) k = doc_->at(k).next;
  return Ref(doc_, k);
}

inline FastJson::Iterator FastJson::Ref::begin() const {
  return Iterator(doc_, is_array() || is_object() ? node().first : -1);
}

inline FastJson::Iterator FastJson::Ref::end() const { return Iterator(doc_, -1); }

// Like nlohmann, asking a value for the wrong type is an error, not a default.
template <>
inline double FastJson::Ref::get<double>() const {
  if (!is_number()) throw std::logic_error("FastJson: not a number");
  return node().number;
}
template <>
inline bool FastJson::Ref::get<bool>() const {
  if (!is_boolean()) throw std::logic_error("FastJson: not a boolean");
  return node().boolean;
}
template <>
inline std::string FastJson::Ref::get<std::string>() const {
  if (!is_string()) throw std::logic_error("FastJson: not a string");
  return std::string(node().text);
}

}  // namespace relpos::detail
