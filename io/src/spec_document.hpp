#pragma once
// How the spec checks (spec_parse.cpp) see the document simdjson read: a value or nothing
// (Json), the path that names it in messages (Path), an object's feature names (FeatureNames).
#include <simdjson.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "json_path.hpp"

namespace relpos::detail {

namespace dom = simdjson::dom;

// A JSON path ("constraints[2].fixed"), spelled out only when a message needs it: each level
// holds its parent and its key or index, so descending into a valid spec builds no strings.
class Path {
 public:
  Path(const char* root_key) : key_(root_key) {}  // NOLINT: "" is the document itself
  Path(const Path& parent, std::string_view key) : parent_(&parent), key_(key) {}
  Path(const Path& parent, std::size_t index) : parent_(&parent), index_(index), indexed_(true) {}
  std::string str() const {
    std::string s = parent_ != nullptr ? parent_->str() : std::string();
    if (indexed_)
      appendPathIndex(s, index_);
    else if (parent_ != nullptr || !key_.empty())  // the root "" is the document: no component
      appendPathKey(s, key_);
    return s;
  }
  // How many arrays and objects hold the value: its path's components.
  std::size_t depth() const {
    const bool component = parent_ != nullptr || indexed_ || !key_.empty();
    return (parent_ != nullptr ? parent_->depth() : 0) + (component ? 1 : 0);
  }

 private:
  const Path* parent_ = nullptr;
  std::string_view key_;
  std::size_t index_ = 0;
  bool indexed_ = false;
};

// A value of the document as the checks read it: an element, or nothing (a missing key).
class Json {
 public:
  Json() = default;
  explicit Json(dom::element e) : e_(e), present_(true) {}

  bool present() const { return present_; }
  bool is_object() const { return is(dom::element_type::OBJECT); }
  bool is_array() const { return is(dom::element_type::ARRAY); }
  bool is_string() const { return is(dom::element_type::STRING); }
  bool is_boolean() const { return is(dom::element_type::BOOL); }
  bool is_number() const {
    return is(dom::element_type::DOUBLE) || is(dom::element_type::INT64) ||
           is(dom::element_type::UINT64);
  }
  // nlohmann's names, which the messages have always used.
  const char* type_name() const {
    if (!present_) return "null";
    switch (e_.type()) {
      case dom::element_type::OBJECT:
        return "object";
      case dom::element_type::ARRAY:
        return "array";
      case dom::element_type::STRING:
        return "string";
      case dom::element_type::BOOL:
        return "boolean";
      case dom::element_type::NULL_VALUE:
        return "null";
      default:
        return "number";
    }
  }
  // Callers check the type first.
  double number() const { return e_.get_double().value_unsafe(); }
  std::string_view string() const { return e_.get_string().value_unsafe(); }
  bool boolean() const { return e_.get_bool().value_unsafe(); }
  dom::object object() const { return e_.get_object().value_unsafe(); }
  dom::array array() const { return e_.get_array().value_unsafe(); }
  dom::element element() const { return e_; }
  std::size_t size() const {
    return is_object() ? object().size() : is_array() ? array().size() : 0;
  }
  bool operator==(std::string_view s) const { return is_string() && string() == s; }
  // A member (nothing when this is not an object or has no such key).
  Json operator[](std::string_view key) const {
    dom::element v;
    if (!is_object() || object().at_key(key).get(v) != simdjson::SUCCESS) return Json();
    return Json(v);
  }

 private:
  bool is(dom::element_type t) const { return present_ && e_.type() == t; }
  dom::element e_;
  bool present_ = false;
};

// An object's feature names to their index in ObjectSpec::features: a scan for the usual
// handful, a hash map from kScanned on (40,000 features and as many constraints stay linear).
// The names are views into the document, which outlives the parse.
class FeatureNames {
 public:
  const std::size_t* find(std::string_view name) const {
    if (entries_.size() <= kScanned) {
      for (const auto& e : entries_)
        if (e.first == name) return &e.second;
      return nullptr;
    }
    const auto it = map_.find(name);
    return it == map_.end() ? nullptr : &it->second;
  }
  // False when the name is already there.
  bool add(std::string_view name, std::size_t index) {
    if (find(name) != nullptr) return false;
    entries_.emplace_back(name, index);
    if (entries_.size() == kScanned + 1)
      for (const auto& e : entries_) map_.emplace(e.first, e.second);
    else if (entries_.size() > kScanned + 1)
      map_.emplace(name, index);
    return true;
  }

 private:
  static constexpr std::size_t kScanned = 32;
  std::vector<std::pair<std::string_view, std::size_t>> entries_;
  std::unordered_map<std::string_view, std::size_t> map_;
};

}  // namespace relpos::detail
