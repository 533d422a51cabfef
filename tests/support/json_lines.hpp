#pragma once
// The lines of a command's JSONL output, each parsed; a line that is not a whole JSON value in
// UTF-8 (nlohmann refuses any other) fails the test.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace relpos::test {

inline std::vector<nlohmann::json> parsedLines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    EXPECT_FALSE(j.is_discarded()) << "not a whole JSON line in UTF-8: " << line.substr(0, 200);
    lines.push_back(j);
  }
  return lines;
}

}  // namespace relpos::test
