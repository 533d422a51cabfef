#include "json_tree.hpp"

#include <nlohmann/json.hpp>

namespace relpos::fuzz {

JsonNode* JsonNode::member(const std::string& key) {
  if (kind != Kind::kObject) return nullptr;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i] == key) return &items[i];
  return nullptr;
}

void JsonNode::set(const std::string& key, JsonNode value) {
  if (JsonNode* m = member(key)) {
    *m = std::move(value);
    return;
  }
  keys.push_back(key);
  items.push_back(std::move(value));
}

void JsonNode::erase(const std::string& key) {
  for (std::size_t i = keys.size(); i-- > 0;) {
    if (keys[i] != key) continue;
    keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(i));
  }
}

std::string escapedBody(const std::string& s) {
  const std::string quoted =
      nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return quoted.substr(1, quoted.size() - 2);
}

JsonNode fromJson(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      JsonNode n = JsonNode::object();
      for (const auto& [k, v] : j.items()) {
        n.keys.push_back(escapedBody(k));
        n.items.push_back(fromJson(v));
      }
      return n;
    }
    case nlohmann::json::value_t::array: {
      JsonNode n = JsonNode::array();
      for (const auto& v : j) n.items.push_back(fromJson(v));
      return n;
    }
    case nlohmann::json::value_t::string:
      return JsonNode::string(escapedBody(j.get<std::string>()));
    case nlohmann::json::value_t::boolean:
      return JsonNode::boolean(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return JsonNode::number(j.dump());
    default:
      return JsonNode::null();
  }
}

namespace {

void write(const JsonNode& n, int indent, int depth, std::string& out) {
  auto newline = [&](int d) {
    if (indent <= 0) return;
    out += '\n';
    out.append(static_cast<std::size_t>(indent * d), ' ');
  };
  switch (n.kind) {
    case JsonNode::Kind::kNull:
      out += "null";
      return;
    case JsonNode::Kind::kBool:
    case JsonNode::Kind::kNumber:
    case JsonNode::Kind::kRaw:
      out += n.text;
      return;
    case JsonNode::Kind::kString:
      out += '"';
      out += n.text;
      out += '"';
      return;
    case JsonNode::Kind::kArray:
    case JsonNode::Kind::kObject: {
      const bool object = n.kind == JsonNode::Kind::kObject;
      out += object ? '{' : '[';
      for (std::size_t i = 0; i < n.items.size(); ++i) {
        if (i) out += ',';
        newline(depth + 1);
        if (object) {
          out += '"';
          out += i < n.keys.size() ? n.keys[i] : std::string();
          out += indent > 0 ? "\": " : "\":";
        }
        write(n.items[i], indent, depth + 1, out);
      }
      if (!n.items.empty()) newline(depth);
      out += object ? '}' : ']';
      return;
    }
  }
}

}  // namespace

std::string serialize(const JsonNode& node, int indent) {
  std::string out;
  write(node, indent, 0, out);
  return out;
}

}  // namespace relpos::fuzz
