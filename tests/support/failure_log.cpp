#include "failure_log.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

namespace relpos::test {

void FailureLog::add(const std::string& group, const std::string& kind, const std::string& cause,
                     const std::string& details) {
  ++total_;
  int& last = last_failed_[group];
  if (last != cases_[group]) {
    last = cases_[group];
    ++failing_[group];
  }
  ++by_kind_[{group, kind}];
  ++by_cause_[{group, kind + ": " + cause}];
  std::vector<std::string>& kept = shown_[{group, kind}];
  const std::string text = "[" + group + "] " + kind + " (" + cause + ")\n" + details;
  // Stable: among equally short ones, the first found stays.
  kept.insert(std::upper_bound(
                  kept.begin(), kept.end(), text,
                  [](const std::string& a, const std::string& b) { return a.size() < b.size(); }),
              text);
  if (static_cast<int>(kept.size()) > shown_per_kind_) kept.pop_back();
}

void FailureLog::report(const std::string& title) const {
  for (const auto& [key, texts] : shown_)
    for (const std::string& t : texts) ADD_FAILURE() << t;
  const std::string t = table(title);
  std::printf("%s", t.c_str());
  EXPECT_EQ(total_, 0) << "failures by kind and cause: the table above";
}

std::string FailureLog::table(const std::string& title) const {
  std::ostringstream os;
  os << "==== " << title << ": " << total_ << " failures ====\n";
  for (const auto& [group, n] : cases_) {
    const auto u = unhandled_.find(group);
    const auto f = failing_.find(group);
    os << group << ": " << n << " cases, " << (u == unhandled_.end() ? 0 : u->second)
       << " unhandled, " << (f == failing_.end() ? 0 : f->second) << " failing";
    for (const auto& [key, k] : by_kind_)
      if (key.first == group) os << ", " << k << " " << key.second;
    os << "\n";
    // The most frequent causes first (ties in name order), at most eight per group.
    std::vector<std::pair<int, std::string>> causes;
    for (const auto& [key, k] : by_cause_)
      if (key.first == group) causes.emplace_back(-k, key.second);
    std::sort(causes.begin(), causes.end());
    for (std::size_t i = 0; i < causes.size() && i < 8; ++i)
      os << "    " << -causes[i].first << " x " << causes[i].second << "\n";
  }
  return os.str();
}

}  // namespace relpos::test
