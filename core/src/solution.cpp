#include "relpos/core/solution.hpp"

#include <cstring>
#include <sstream>

namespace relpos {

const char* toString(Status s) {
  switch (s) {
    case Status::kNotSolved:
      return "not-solved";
    case Status::kSolved:
      return "solved";
    case Status::kInconsistent:
      return "inconsistent";
    case Status::kUnhandled:
      return "unhandled";
  }
  return "?";
}

const char* toString(ParamKind k) {
  switch (k) {
    case ParamKind::kAngle:
      return "angle";
    case ParamKind::kLength:
      return "length";
    case ParamKind::kOther:
      return "other";
  }
  return "other";
}

Solution::Solution() {
  branches.reserve(64);
  conflicts.reserve(64);
  redundant.reserve(64);
  rules.reserve(64);
  message.reserve(512);
}

void Solution::clear() {
  status = Status::kNotSolved;
  complete = false;
  isolated_complete = false;
  message.clear();
  branches.clear();
  conflicts.clear();
  redundant.clear();
  rules.clear();
  solve_us = 0.0;
}

void Solution::noteRule(RuleCaseId id) {
  const char* name = rule_names->name(id);
  for (const RuleCaseId& r : rules)
    if (r == id || std::strcmp(rule_names->name(r), name) == 0) return;
  rules.push_back(id);
}

Solution unhandledAfterThrow(const Solution& solution, const char* during,
                             const std::string& what) {
  std::string plugins;
  for (const Branch& b : solution.branches)
    if (b.origin && plugins.find(b.origin) == std::string::npos)
      plugins += std::string(plugins.empty() ? "" : ", ") + b.origin;
  Solution out;
  out.status = Status::kUnhandled;
  out.message = plugins.empty()
                    ? std::string("internal error while ") + during + ": " + what
                    : "a manifold of plugin " + plugins + " threw while " + during + ": " + what;
  out.rule_names = solution.rule_names;
  out.rules = solution.rules;
  out.solve_us = solution.solve_us;
  return out;
}

std::string Solution::briefReport() const {
  std::ostringstream os;
  os << toString(status) << ": " << branches.size() << " branch(es)";
  for (std::size_t i = 0; i < branches.size(); ++i)
    os << (i ? ", " : " [") << branches[i].manifold->dof() << " DOF"
       << (i + 1 == branches.size() ? "]" : "");
  if (!message.empty()) os << " — " << message;
  return os.str();
}

}  // namespace relpos
