#pragma once
// Collects the failures of a property sweep by group (a transform, a degenerate family) and kind
// (status changed, NaN, violating pose, ...): every one is counted, the few shortest of each
// (the most nearly minimal reproductions: fewest constraints) become gtest failures with their
// reproduction, and the table of counts and causes (the rules that fired, the status) tells what
// breaks where and how often.
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace relpos::test {

class FailureLog {
 public:
  explicit FailureLog(int shown_per_kind = 3) : shown_per_kind_(shown_per_kind) {}
  // `cause`: what produced it (status and rules), for the table; `details`: the reproduction.
  // Nothing is reported until report().
  void add(const std::string& group, const std::string& kind, const std::string& cause,
           const std::string& details);
  // Starts a case of the group (failing or not: add() then refers to it); unhandled() marks it
  // answered `unhandled`.
  void count(const std::string& group) { ++cases_[group]; }
  void unhandled(const std::string& group) { ++unhandled_[group]; }
  int total() const { return total_; }
  // The table: per group, cases, unhandled, failures by kind, and the most frequent causes.
  std::string table(const std::string& title) const;
  // Prints the table and makes the kept reproductions gtest failures (none: the sweep passed).
  void report(const std::string& title) const;

 private:
  int shown_per_kind_;
  int total_ = 0;
  std::map<std::string, int> cases_, unhandled_;
  std::map<std::string, int> failing_;      // cases with at least one failure
  std::map<std::string, int> last_failed_;  // the case number that failed last
  std::map<std::pair<std::string, std::string>, int> by_kind_;
  std::map<std::pair<std::string, std::string>, int> by_cause_;  // (group, kind: cause)
  // The shortest reproductions of each (group, kind), shortest first.
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> shown_;
};

}  // namespace relpos::test
