#pragma once
// How relpos spells a JSON path in its messages: keys joined by '.', array indices in brackets
// ("constraints[2].fixed"). One place, so the spec checks, the duplicate-key walk and the JSON
// scan name a value the same way.
#include <cstddef>
#include <string>
#include <string_view>

namespace relpos::detail {

// A key that is the empty string is spelled [""]: joined by '.' it would vanish, and a member ""
// of the spec itself would be named by the empty path, which is the document's.
inline void appendPathKey(std::string& path, std::string_view key) {
  if (key.empty()) {
    path += "[\"\"]";
    return;
  }
  if (!path.empty()) path += '.';
  path += key;
}

inline void appendPathIndex(std::string& path, std::size_t index) {
  path += '[';
  path += std::to_string(index);
  path += ']';
}

}  // namespace relpos::detail
