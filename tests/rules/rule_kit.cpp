#include "rule_kit.hpp"

#include <gtest/gtest.h>

#include "evaluator.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/plugins/conformance.hpp"

namespace relpos::test {

std::vector<Fundamental> fundamentalsOf(const Problem& p) {
  std::vector<Fundamental> out;
  for (std::size_t i = 0; i < p.constraints.size(); ++i) {
    const InputConstraint& c = p.constraints[i];
    Decomposition d;
    const ConstraintType* type = builtinRegistry().constraintType(c.type);
    type->decompose(c, c.fixed.placed(p.fixed.pose), SourceMask{1} << i, d, type->context);
    if (!d.alternatives.empty())
      for (const Fundamental& f : d.alternatives[0]) out.push_back(f);
  }
  return out;
}

RuleOutput applyRule(const std::string& family, const Problem& p, std::string* case_name,
                     const Tolerance& tol) {
  return applyRule(family, fundamentalsOf(p), case_name, tol);
}

RuleOutput applyRule(const std::string& family, const std::vector<Fundamental>& fs,
                     std::string* case_name, const Tolerance& tol) {
  RuleOutput out;
  case_name->clear();
  EXPECT_GE(fs.size(), 2u);
  if (fs.size() < 2) return out;
  for (const RuleInfo& rule : builtinRegistry().rules()) {
    if (rule.name != family) continue;
    const bool in_order = fs[0].kind == rule.first && fs[1].kind == rule.second;
    EXPECT_TRUE(in_order || (fs[1].kind == rule.first && fs[0].kind == rule.second)) << family;
    const Fundamental& a = in_order ? fs[0] : fs[1];
    const Fundamental& b = in_order ? fs[1] : fs[0];
    rule.fn(a, b, tol, out, rule.context);
    EXPECT_LT(out.fired, static_cast<int>(rule.cases.size())) << family << ": a case without a row";
    if (out.fired >= 0) *case_name = rule.firedName(out.fired);
    return out;
  }
  ADD_FAILURE() << "no rule family " << family;
  return out;
}

bool satisfiesInputs(const Problem& p, const Isometry3d& X_WM) {
  return worstViolation(p, X_WM) <= 1e-9;
}

bool satisfiesAnAlternative(const RuleOutput& out, const Isometry3d& X_WM) {
  for (const auto& alt : out.alternatives) {
    bool all = true;
    for (const Fundamental& f : alt) all = all && plugins::fundamentalResidual(f, X_WM) <= 1e-9;
    if (all) return true;
  }
  return false;
}

void makeRange(Problem& p, std::size_t i, double lo, double hi) {
  InputConstraint& c = p.constraints.at(i);
  c.has_value = false;
  c.min = lo;
  c.max = hi;
}

Isometry3d poseOf(const Vector3d& t, double angle, const Vector3d& axis) {
  Isometry3d X = Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  X.translation() = t;
  return X;
}

}  // namespace relpos::test
